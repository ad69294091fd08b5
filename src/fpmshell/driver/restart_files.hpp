// restart.bin (model-format.md "Restart files"): the whole state of a dynamic run after a
// completed step, so that --resume continues bitwise as if the run had never stopped. Written
// every `every` wall seconds and at the end of the run (when `every` > 0), and always when the
// run pauses (a signal, --stop-at-step).
//
// Layout after the header: section "layout" (the number of pieces, 0 for one process, and the
// step), the solver's sections, section "driver" (next history row and frame times, wall seconds
// so far), then the sections of the observers that keep a state (history, energy, fields), in
// the order of the observer list.
//
// On several ranks every rank writes its piece, restart_rankR_stepN.bin (the state of the
// particles it owns and of the elements it computes: ExplicitSolver::save_piece), and rank 0,
// once every piece is on disk, restart.bin without that state; then the pieces of older files
// are removed. A resume on any number of ranks reads restart.bin and every piece it names: no
// rank gathers the state to write it. The file a run cut short while writing leaves behind
// still names its own pieces, which are kept until a newer file is complete.
#pragma once

#include <chrono>
#include <filesystem>

#include "fpmshell/driver/output_observer.hpp"
#include "fpmshell/driver/output_schedule.hpp"
#include "fpmshell/model/particle_separation.hpp"

namespace fpmshell {

class RestartFiles final : public OutputObserver {
public:
    /// `results`: the observers whose state the file holds (flushed before each write);
    /// `every`: wall seconds between files, 0 for none but those of a pause.
    RestartFiles(std::filesystem::path path, double every, const OutputSchedule& schedule,
                 OutputObserver& results);

    void start(const ExplicitSolver& solver) override;
    void step_done(const ExplicitSolver& solver, const StepReport& report) override;

    /// Restores a run from the restart file at `path`: the solver, the schedule and every
    /// result observer (before their start). Returns the wall seconds of the earlier segments.
    /// Throws InputError (naming the file) when it does not fit the model or is damaged.
    static double resume(const std::filesystem::path& path, ExplicitSolver& solver,
                         OutputSchedule& schedule, OutputObserver& results);
    /// resume without the result files' state (the ranks of a distributed run other than 0,
    /// which write no results but their pieces of the frames and restart files).
    static double resume_solver(const std::filesystem::path& path, ExplicitSolver& solver,
                                OutputSchedule& schedule);
    /// The separations of the run (theory.md §7.7) in the restart file at `path`, whose model
    /// has n_elements elements: the resumed solver is built from replay_separations of the
    /// model with them. Throws InputError when the file is damaged.
    static SeparationHistory separation_history(const std::filesystem::path& path,
                                                Index n_elements);
    /// Whether step_done would write the restart file for this report, by the wall clock or
    /// at the end (not counting a pause); a distributed run asks rank 0's and tells every
    /// rank's step_done the agreed answer (StepReport::restart_agreed): writing is collective.
    [[nodiscard]] bool clock_due(const StepReport& report) const;

private:
    using Clock = std::chrono::steady_clock;

    void write(const ExplicitSolver& solver, double wall_seconds);

    std::filesystem::path path_;
    double every_;
    const OutputSchedule& schedule_;
    OutputObserver& results_;
    Clock::time_point last_write_ = Clock::now();
};

}  // namespace fpmshell
