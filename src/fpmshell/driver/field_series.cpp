// VTU frame series observer; described in field_series.hpp.
#include "fpmshell/driver/field_series.hpp"

#include <fmt/format.h>

#include <exception>
#include <stdexcept>

#include "fpmshell/core/communicator.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/io/run_directory.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

FieldSeries::FieldSeries(const Model& model, std::filesystem::path dir,
                         std::vector<OutputField> fields, LogSink log)
    : model_(model), dir_(std::move(dir)), fields_(std::move(fields)), log_(std::move(log)) {}

void FieldSeries::load(RestartReader& restart) {
    restart.section("fields");
    restart(frames_);
    frame_count_ = frames_.size();
    resumed_ = true;
}

void FieldSeries::start(const ExplicitSolver& /*solver*/) {
    const Communicator& comm = Communicator::world();
    if (comm.root()) {
        if (resumed_) remove_frames_from(dir_, static_cast<int>(frames_.size()));
        pvd_.emplace(dir_ / "fields.pvd");
        for (const auto& [time, file] : frames_) pvd_->add(time, file);
    }
    // after rank 0 has removed the frames past the restart point, before any rank writes one
    if (comm.distributed())
        frame_count_ = static_cast<std::size_t>(
            comm.max(comm.root() ? static_cast<long>(frames_.size()) : 0L));
}

std::string FieldSeries::write_pieces(const ExplicitSolver& solver, Real time,
                                      const std::vector<Vec3>& positions, std::size_t number,
                                      const VtuFormat& format) {
    const Communicator& comm = Communicator::world();
    // the solver's mesh: after a particle separation (theory.md §7.7) the separated one, cut
    // anew over the ranks (its particles, more after every separation, tell it apart)
    if (!piece_ || piece_particles_ != solver.model().n_particles()) {
        piece_ = frame_piece(solver.model(), solver.elements().computed_elements(), comm.root());
        piece_particles_ = solver.model().n_particles();
    }
    const std::string stem = fmt::format("frame_{:05d}", number);
    std::string error;
    try {
        field_frame(fields_, {solver.model(), solver, positions}, time, *piece_, frame_);
        write_vtu(dir_ / k_fields_folder / fmt::format("{}_rank{}.vtu", stem, comm.rank()), frame_,
                  format);
    } catch (const std::exception& e) {
        error = e.what();
    }
    // every piece on disk (or one rank's failure known to all) before the .pvtu names them
    if (comm.max(error.empty() ? 0L : 1L) != 0)
        throw std::runtime_error(
            error.empty() ? fmt::format("another rank could not write its piece of {}", stem)
                          : error);
    const std::string file = fmt::format("{}/{}.pvtu", k_fields_folder, stem);
    if (comm.root()) {
        std::vector<std::string> pieces;
        for (int r = 0; r < comm.size(); ++r)
            pieces.push_back(fmt::format("{}_rank{}.vtu", stem, r));
        write_pvtu(dir_ / file, frame_, pieces);
    }
    return file;
}

void FieldSeries::frame(const ExplicitSolver& solver, Real time,
                        const std::vector<Vec3>& positions) {
    const OutputControl& output = model_.output;
    const VtuFormat format(output.fields_encoding == FieldsEncoding::Base64  ? VtuEncoding::Base64
                           : output.fields_encoding == FieldsEncoding::Ascii ? VtuEncoding::Ascii
                                                                             : VtuEncoding::Raw,
                           output.fields_zlib ? VtuCompression::Zlib : VtuCompression::None);
    std::string file;
    if (Communicator::world().distributed()) {
        file = write_pieces(solver, time, positions, frame_count_, format);
    } else {
        file = fmt::format("{}/frame_{:05d}.vtu", k_fields_folder, frame_count_);
        field_frame(fields_, {solver.model(), solver, positions}, time, frame_);
        write_vtu(dir_ / file, frame_, format);
    }
    ++frame_count_;
    if (!pvd_) return;  // a rank other than 0
    frames_.emplace_back(time, file);
    pvd_->add(time, file);
}

void FieldSeries::failure(const ExplicitSolver& solver, std::string_view /*error*/,
                          const std::vector<Vec3>& last_good_positions) {
    try {
        frame(solver, solver.time(), last_good_positions);
    } catch (const std::exception& e) {
        log_(fmt::format("could not write the last frame: {}", e.what()));
    }
}

void FieldSeries::save(RestartWriter& restart) const {
    restart.section("fields");
    restart(frames_);
}

}  // namespace fpmshell
