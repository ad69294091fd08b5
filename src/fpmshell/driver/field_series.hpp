// fields.pvd + fields/frame_NNNNN.vtu (model-format.md "Results in DIR"): a VTU frame of the
// field list at every frame time, and the last good state of a failed run; the .pvd lists
// them with their times. The frames listed so far travel in restart.bin; a resumed run deletes
// the frames written after its restart file and numbers on from there.
//
// On several ranks every rank writes its piece of each frame (fields/frame_NNNNN_rankR.vtu:
// the elements it computes, output_fields.hpp FramePiece) and rank 0 the frame's .pvtu that
// lists them, once every piece is on disk: no rank gathers a frame.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fpmshell/driver/output_fields.hpp"
#include "fpmshell/driver/output_observer.hpp"
#include "fpmshell/io/vtu_writer.hpp"

namespace fpmshell {

class FieldSeries final : public OutputObserver {
public:
    /// Receives a line for the log when the last good frame of a failed run cannot be written.
    using LogSink = std::function<void(const std::string&)>;

    FieldSeries(const Model& model, std::filesystem::path dir, std::vector<OutputField> fields,
                LogSink log);

    void load(RestartReader& restart) override;
    /// Writes fields.pvd (empty, or listing the frames of the restart file). On several ranks
    /// collective: rank 0 tells the others how many frames there are.
    void start(const ExplicitSolver& solver) override;
    /// On several ranks collective (every rank writes its piece).
    void frame(const ExplicitSolver& solver, Real time,
               const std::vector<Vec3>& positions) override;
    /// Writes the frame of the last good positions at the solver's time.
    void failure(const ExplicitSolver& solver, std::string_view error,
                 const std::vector<Vec3>& last_good_positions) override;
    void save(RestartWriter& restart) const override;

private:
    /// This rank's piece of frame `number` at `time`; on rank 0 also the .pvtu (the name
    /// returned, relative to dir_). Throws std::runtime_error on every rank when any rank
    /// could not write its piece.
    std::string write_pieces(const ExplicitSolver& solver, Real time,
                             const std::vector<Vec3>& positions, std::size_t number,
                             const VtuFormat& format);

    const Model& model_;
    std::filesystem::path dir_;
    std::vector<OutputField> fields_;
    LogSink log_;
    /// (time, path relative to dir_) of every frame so far (on rank 0; the others count them).
    std::vector<std::pair<Real, std::string>> frames_;
    std::size_t frame_count_ = 0;
    bool resumed_ = false;
    std::optional<PvdSeries> pvd_;  ///< created at start, so that a refused resume writes nothing
    Index piece_particles_ = 0;     ///< the particles of the mesh piece_ was cut from
    std::optional<FramePiece> piece_;  ///< on several ranks: this rank's, made at the first frame
    FieldFrame frame_;                 ///< the last frame, its memory reused by the next
};

}  // namespace fpmshell
