// Progress line and log lines of a run; described in run_report.hpp.
#include "fpmshell/driver/run_report.hpp"

#include <fmt/format.h>

#include <string>
#include <utility>

#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

ProgressReport::ProgressReport(LogFile& log, Real end_time, bool quiet)
    : log_(log), progress_(end_time, quiet, [&log](const std::string& s) { log.line(s); }) {
    log_.set_progress(&progress_);
}

ProgressReport::~ProgressReport() { log_.set_progress(nullptr); }

void ProgressReport::start(const ExplicitSolver& solver) { progress_.resume_from(solver.time()); }

void ProgressReport::step_done(const ExplicitSolver& solver, const StepReport& report) {
    progress_.update(report.time, solver.steps(), solver.last_dt(),
                     report.residual_ratio.value_or(solver.energy().error()));
}

void ProgressReport::failure(const ExplicitSolver& solver, std::string_view error,
                             const std::vector<Vec3>& /*last_good_positions*/) {
    progress_.finish();
    log_.print("error: {}", error);
    log_.print("the last good state (t = {:.6g}) is in the last frame of fields.pvd",
               solver.time());
}

void ProgressReport::finish(const ExplicitSolver& /*solver*/, const RunEnd& end) {
    progress_.finish();
    if (!end.message.empty()) log_.line(end.message);
}

ClosingReport::ClosingReport(LogFile& log, std::filesystem::path dir)
    : log_(log), dir_(std::move(dir)) {}

void ClosingReport::finish(const ExplicitSolver& solver, const RunEnd& end) {
    const double seconds = end.wall_seconds;
    log_.print(
        "{} after {} steps, t = {:.6g}, energy error {:.3f} %, {:.2f} s wall, {:.3g} "
        "element-steps/s",
        end.exit_code == 0 ? "finished" : "stopped", solver.steps(), solver.time(),
        100 * solver.energy().error(), seconds,
        seconds > 0 ? static_cast<double>(solver.element_steps()) / seconds : 0.0);
    if (const ContactStatistics* c = solver.contact_statistics()) {
        log_.print(
            "contact: largest penetration {:.4g} ({:.2f} % of the thickness) at step {}, "
            "particle {}{}",
            c->max_penetration, 100 * c->max_penetration_ratio, c->max_penetration_step,
            c->max_penetration_particle + 1,
            c->max_penetration_element >= 0
                ? fmt::format(", element {}", c->max_penetration_element + 1)
                : std::string(" (rigid body)"));
        log_.print(
            "contact: up to {} contact forces, up to {} sweeps ({} steps unconverged), {} pairs "
            "held inside, {} searches, {:.2f} s ({:.1f} % of the time loop)",
            c->max_active, c->max_sweeps, c->unconverged_steps, c->held_penetrations, c->searches,
            c->seconds, seconds > 0 ? 100 * c->seconds / seconds : 0.0);
        if (c->initial_penetrations > 0)
            log_.print(
                "contact: {} particles started closer to a face than their thickness offsets "
                "(initial penetrations); the contact leaves those pairs out (exclusion radius, "
                "theory.md R8)",
                c->initial_penetrations);
    }
    log_.print("results in {}", dir_.string());
}

}  // namespace fpmshell
