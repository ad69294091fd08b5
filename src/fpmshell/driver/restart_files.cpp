// Restart file observer; the cadence and layout are in restart_files.hpp.
#include "fpmshell/driver/restart_files.hpp"

#include <utility>

#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

RestartFiles::RestartFiles(std::filesystem::path path, double every, const OutputSchedule& schedule,
                           OutputObserver& results)
    : path_(std::move(path)), every_(every), schedule_(schedule), results_(results) {}

void RestartFiles::start(const ExplicitSolver& /*solver*/) { last_write_ = Clock::now(); }

bool RestartFiles::clock_due(const StepReport& report) const {
    return every_ > 0 &&
           (std::chrono::duration<double>(Clock::now() - last_write_).count() >= every_ ||
            report.outcome == StepOutcome::Ends);
}

void RestartFiles::step_done(const ExplicitSolver& solver, const StepReport& report) {
    if (clock_due(report) || report.outcome == StepOutcome::Pauses)
        write(solver, report.wall_seconds);
}

void RestartFiles::write(const ExplicitSolver& solver, double wall_seconds) {
    results_.flush();  // the files on disk hold at least what the restart file holds
    RestartWriter w;
    solver.save(w);
    w.section("driver");
    w(schedule_, wall_seconds);
    results_.save(w);
    w.save(path_);
    last_write_ = Clock::now();
}

double RestartFiles::resume(const std::filesystem::path& path, ExplicitSolver& solver,
                            OutputSchedule& schedule, OutputObserver& results) {
    RestartReader r(path);
    solver.load(r);
    r.section("driver");
    double wall_seconds = 0;
    r(schedule, wall_seconds);
    if (!schedule.fits_time(solver.time()))
        r.fail("restart file is damaged: its next output times do not fit its time");
    results.load(r);
    r.finish();
    return wall_seconds;
}

double RestartFiles::resume_solver(const std::filesystem::path& path, ExplicitSolver& solver,
                                   OutputSchedule& schedule) {
    RestartReader r(path);
    solver.load(r);
    r.section("driver");
    double wall_seconds = 0;
    r(schedule, wall_seconds);
    if (!schedule.fits_time(solver.time()))
        r.fail("restart file is damaged: its next output times do not fit its time");
    return wall_seconds;
}

}  // namespace fpmshell
