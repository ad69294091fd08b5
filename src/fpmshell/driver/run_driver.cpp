// The run: the solver advances, and the result observers (output_observer.hpp) are told what
// happened after every step; the observers write every result file.
#include "fpmshell/driver/run_driver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <string_view>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "fpmshell/core/communicator.hpp"
#include "fpmshell/core/errors.hpp"
#include "fpmshell/driver/energy_file.hpp"
#include "fpmshell/driver/field_series.hpp"
#include "fpmshell/driver/history_file.hpp"
#include "fpmshell/driver/history_sampler.hpp"
#include "fpmshell/driver/interrupt_guard.hpp"
#include "fpmshell/driver/output_schedule.hpp"
#include "fpmshell/driver/plastic_strain_peaks.hpp"
#include "fpmshell/driver/restart_files.hpp"
#include "fpmshell/driver/run_report.hpp"
#include "fpmshell/driver/summary_file.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/io/run_directory.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "fpmshell/solver/separating_step.hpp"

namespace fpmshell {
namespace {

/// Wall seconds of the time loop, over every segment of a resumed run.
class WallClock {
public:
    explicit WallClock(double before) : before_(before) {}
    [[nodiscard]] double seconds() const {
        return before_ + std::chrono::duration<double>(Clock::now() - start_).count();
    }

private:
    using Clock = std::chrono::steady_clock;
    double before_;
    Clock::time_point start_ = Clock::now();
};

/// What the time loops work with.
struct Run {
    const Model& model;
    const RunOptions& options;
    /// the solver, replaced by its successor's at a particle separation (theory.md §7.7)
    std::unique_ptr<ExplicitSolver>& solver;
    std::unique_ptr<Model>& separated;  ///< the model of the last separation (null: none)
    OutputSchedule& schedule;
    OutputObserver& out;
    LogFile& log;
    WallClock clock;
    const RestartFiles* restart = nullptr;  ///< rank 0's restart observer (null: none)
};

/// How a run ended, before its wall time and threads are known.
RunEnd run_end(int exit_code, std::string reason, std::string message = {}) {
    RunEnd end;
    end.exit_code = exit_code;
    end.reason = std::move(reason);
    end.message = std::move(message);
    return end;
}

int use_threads(int requested) {
#ifdef _OPENMP
    if (requested > 0) omp_set_num_threads(requested);
    return omp_get_max_threads();
#else
    (void)requested;
    return 1;
#endif
}

/// control.end_when_body_stops: the body no longer moves along its initial velocity (v^{n+1/2}).
bool body_has_stopped(const Model& model, const ExplicitSolver& solver) {
    if (model.control.end_body < 0) return false;
    const std::size_t b = static_cast<std::size_t>(model.control.end_body);
    return solver.bodies()[b].v.dot(model.rigid_bodies[b].velocity) <= 0;
}

/// The longest step to take towards `end`. No short step at the end: over the last
/// k_end_steps steps the remaining time is cut into equal steps, so that no step is more than
/// 1 / k_end_steps shorter than the one before. The leapfrog kinetic energy 1/2 v^{n-1/2}.M
/// v^{n+1/2} of a mode near the stability limit changes with the step (theory.md §6.8): a last
/// step ten times shorter showed as a 0.1 % jump of the energy error, and one half as long as a
/// 40 % jump on a free triangle (a fragment, §7.7).
constexpr Real k_end_steps = 16;
Real step_limit(const ExplicitSolver& solver, Real end) {
    const Real remaining = end - solver.time();
    const Real last = solver.last_dt();
    if (!(last > 0) || remaining >= k_end_steps * last) return remaining;
    return remaining / std::ceil(remaining / last * (1 - 1e-9));
}

/// A dynamic run from the solver's time to control.end_time, or until the watched rigid body
/// stops, a signal arrives (SIGINT, SIGTERM) or --stop-at-step is reached.
RunEnd advance_in_time(Run& run) {
    const Real end = run.model.control.end_time;
    const long stop_at_step = run.options.stop_at_step;
    const std::string restart = (run.options.output_dir / k_restart_file).string();
    const InterruptGuard interrupts;
    const Communicator& comm = Communicator::world();
    while (run.solver->time() < end * (1 - 1e-12)) {
        separating_step(run.solver, run.separated, step_limit(*run.solver, end));  // §7.7
        ExplicitSolver& solver = *run.solver;
        const Real t = solver.time();
        const bool body_stopped = body_has_stopped(run.model, solver);
        const bool at_end = t >= end * (1 - 1e-12) || body_stopped;
        const bool row = run.schedule.row_due(t, at_end);
        const bool frame = run.schedule.frame_due(t, at_end);
        int signal = at_end ? 0 : InterruptGuard::received();
        std::optional<bool> restart_agreed;  // a distributed run's, for every rank's pieces
        if (comm.distributed()) {
            // one decision for every rank: a signal that any rank received, rank 0's restart
            // clock (every rank writes its piece of a restart file then; history rows and
            // summary.json's peaks are reduced over the ranks, frames written in pieces)
            const bool clock =
                comm.root() && run.restart &&
                run.restart->clock_due({t, std::nullopt,
                                        at_end ? StepOutcome::Ends : StepOutcome::Continues,
                                        run.clock.seconds(), std::nullopt});
            const long flags = comm.max(2L * signal + (clock ? 1 : 0));
            signal = static_cast<int>(flags / 2);
            const bool pausing =
                signal != 0 || (!at_end && stop_at_step > 0 && solver.steps() >= stop_at_step);
            restart_agreed = pausing || (flags & 1) != 0;
        }
        if (row) run.out.sample(solver, t, std::nullopt);
        if (frame) run.out.frame(solver, t, solver.state().x);
        const bool pause =
            signal != 0 || (!at_end && stop_at_step > 0 && solver.steps() >= stop_at_step);
        const StepOutcome outcome = at_end  ? StepOutcome::Ends
                                    : pause ? StepOutcome::Pauses
                                            : StepOutcome::Continues;
        run.out.step_done(solver, {t, std::nullopt, outcome, run.clock.seconds(), restart_agreed});
        if (body_stopped) {
            const std::string& name =
                run.model.rigid_bodies[static_cast<std::size_t>(run.model.control.end_body)].name;
            return run_end(0, fmt::format("completed: rigid body {} stopped", name),
                           fmt::format("the rigid body '{}' has stopped at t = {:.6g} "
                                       "(control.end_when_body_stops): end of the run",
                                       name, t));
        }
        if (signal != 0)  // the shell's convention for a process ended by a signal: 128 + it
            return run_end(
                128 + signal,
                fmt::format("interrupted by {} at step {}: resume with --resume",
                            signal_name(signal), solver.steps()),
                fmt::format("interrupted by {} after step {} at t = {:.6g}; the state is in "
                            "{}: continue with --resume",
                            signal_name(signal), solver.steps(), t, restart));
        if (pause)
            return run_end(
                0, fmt::format("stopped at step {}: resume with --resume", solver.steps()),
                fmt::format("stopped after step {} at t = {:.6g}; continue with --resume "
                            "from {}",
                            solver.steps(), t, restart));
    }
    return run_end(0, "completed");
}

/// A relaxation run: static equilibrium at every load level up to control.end_time.
/// `last_good`: the positions before the level being relaxed.
RunEnd relax_load_levels(Run& run, std::vector<Vec3>& last_good) {
    ExplicitSolver& solver = *run.solver;
    const Real end = run.model.control.end_time;
    const Real step = run.model.output.every > 0 ? run.model.output.every : end;
    const long levels = static_cast<long>(std::ceil(end / step - 1e-9));
    long unconverged = 0;
    for (long k = 1; k <= levels; ++k) {
        const Real t = std::min(end, static_cast<Real>(k) * step);
        last_good = solver.state().x;
        const ExplicitSolver::RelaxResult r = solver.relax(t);
        if (!r.converged) {
            ++unconverged;
            run.log.print(
                "warning: load level {:.6g} did not converge in {} iterations "
                "(residual ratio {:.3e} > tolerance {:.1e})",
                t, r.iterations, r.residual_ratio, run.model.control.tolerance);
        }
        run.out.sample(solver, t, r.converged);
        if (run.schedule.frame_due(t, k == levels)) run.out.frame(solver, t, solver.state().x);
        run.out.step_done(
            solver, {t, r.residual_ratio, k == levels ? StepOutcome::Ends : StepOutcome::Continues,
                     run.clock.seconds(), std::nullopt});
    }
    if (unconverged > 0)
        return run_end(0, fmt::format("completed; {} of {} load levels did not converge",
                                      unconverged, levels));
    return run_end(0, "completed");
}

/// The result files of model-format.md and the run's report, in the order they are told: the
/// progress line first, then the files, the options' observers, and the closing log lines.
struct ResultFiles {
    RestartFiles* restart = nullptr;  ///< dynamic runs
    SummaryFile* summary = nullptr;
};

ResultFiles add_result_files(ObserverList& out, const Model& model, const RunOptions& opt,
                             LogFile& log, const OutputSchedule& schedule) {
    out.add<ProgressReport>(log, model.control.end_time, opt.quiet);
    const HistoryFile& history = out.add<HistoryFile>(model, opt.output_dir);
    out.add<EnergyFile>(model, opt.output_dir);
    out.add<FieldSeries>(model, opt.output_dir, standard_fields(model),
                         [&log](const std::string& line) { log.line(line); });
    ResultFiles files;
    files.summary = &out.add<SummaryFile>(model, opt.output_dir, history);
    if (model.control.mode == SolutionMode::Dynamic)
        files.restart = &out.add<RestartFiles>(opt.output_dir / k_restart_file, opt.restart_every,
                                               schedule, out);
    for (OutputObserver* o : opt.observers) out.attach(*o);
    out.add<ClosingReport>(log, opt.output_dir);
    return files;
}

/// What a run on several ranks does not do yet, refused before it starts (exit 2).
void check_distributable(const Model& model, int ranks) {
    auto refuse = [&](const char* key, const char* what) {
        throw InputError(input_error_text(
            model.source_file, 0, key,
            fmt::format("{} is not supported on several ranks yet ({} ranks): run it on one "
                        "rank (with --threads)",
                        what, ranks)));
    };
    if (model.control.membrane == MembraneKernel::Smoothed)
        refuse("control.membrane", "the smoothed membrane");
}

/// control.mass_scaling (§6.10): the mass added (`when`: at set-up, or by the end of the run),
/// and a warning for every section past added_mass_limit.
void report_mass_scaling(const Model& model, const AddedMass& added, std::string_view when,
                         LogFile& log) {
    const MassScaling& ms = model.control.mass_scaling;
    if (!(ms.time_step > 0)) return;
    const Real physical = added.total_physical();
    log.print("mass scaling to time step {:.6g}, {}: added mass {:.6g} ({:.3g} % of {:.6g})",
              ms.time_step, when, added.total_added(),
              physical > 0 ? 100.0 * added.total_added() / physical : 0.0, physical);
    for (const Index s : added.over_limit(model)) {
        const auto us = static_cast<std::size_t>(s);
        log.print(
            "warning: mass scaling adds {:.6g} to sections.{}, {:.3g} % of its mass {:.6g}, "
            "more than control.mass_scaling.added_mass_limit ({:.3g} %)",
            added.added[us], s, 100.0 * added.added[us] / added.physical[us], added.physical[us],
            100.0 * ms.added_mass_limit);
    }
}

bool all_finite(const std::vector<Vec3>& v) {
    return std::all_of(v.begin(), v.end(), [](const Vec3& a) { return a.allFinite(); });
}

}  // namespace

int run_model(const Model& model, const RunOptions& opt) {
    const Communicator& comm = Communicator::world();
    const int threads = use_threads(opt.threads);
    const bool relaxation = model.control.mode == SolutionMode::Relaxation;
    if (relaxation && (opt.resume || opt.restart_every > 0 || opt.stop_at_step > 0))
        throw InputError(input_error_text(
            model.source_file, 0, "control.mode",
            "restart files (--restart-every, --resume) are for dynamic runs, not for relaxation"));
    if (comm.distributed()) check_distributable(model, comm.size());
    // Rank 0 writes every result file; the others learn whether its folder is ready.
    std::exception_ptr folder_error;
    if (comm.root()) {
        try {
            if (opt.resume)
                prepare_resume_directory(opt.output_dir, model.source_file, opt.overwrite);
            else
                prepare_run_directory(opt.output_dir, model.source_file, opt.overwrite);
        } catch (...) {
            folder_error = std::current_exception();
        }
    }
    if (comm.max(folder_error ? 1 : 0) != 0) {
        if (folder_error) std::rethrow_exception(folder_error);
        return 2;  // rank 0 reports it
    }
    LogFile log(comm.root() ? opt.output_dir / "log.txt" : std::filesystem::path("/dev/null"),
                opt.echo && comm.root());
    log.print("fpmshell {} — {}", FPMSHELL_VERSION, model.title);
    log.print("model {}, {} particles, {} elements, {} thread(s)", model.source_file,
              model.n_particles(), model.n_elements(), threads);
    if (comm.distributed())
        log.print("distributed over {} ranks, {} thread(s) each", comm.size(), threads);
    for (const std::string& note : model.notes) log.print("note: {}", note);

    const std::filesystem::path restart_path = opt.output_dir / k_restart_file;
    // §7.7 a run resumed after its particles separated goes on from the mesh they made
    std::unique_ptr<Model> separated;
    if (opt.resume)
        if (const SeparationHistory history =
                RestartFiles::separation_history(restart_path, model.n_elements());
            !history.splits.empty())
            separated = std::make_unique<Model>(replay_separations(model, history));
    std::unique_ptr<ExplicitSolver> solver_now =
        std::make_unique<ExplicitSolver>(separated ? *separated : model);
    report_mass_scaling(model, solver_now->added_mass(), "at set-up", log);
    OutputSchedule schedule(model);
    ObserverList out;
    // Rank 0 writes every result file; every other rank takes its part in the history rows and
    // writes its pieces of the frames and of the restart files.
    ResultFiles result_files;
    if (comm.root()) {
        result_files = add_result_files(out, model, opt, log, schedule);
    } else {
        out.add<HistoryShare>(model);
        out.add<FieldSeries>(model, opt.output_dir, standard_fields(model),
                             [&log](const std::string& line) { log.line(line); });
        result_files.restart =
            &out.add<RestartFiles>(restart_path, opt.restart_every, schedule, out);
    }
    const RestartFiles* restart = result_files.restart;

    double wall_before = 0;                // wall seconds of the earlier segments of a resumed run
    ExplicitSolver& solver = *solver_now;  // until the time loop (which may replace it, §7.7)
    if (opt.resume) {
        wall_before = comm.root() ? RestartFiles::resume(restart_path, solver, schedule, out)
                                  : RestartFiles::resume_solver(restart_path, solver, schedule);
        log.print("resumed from {} at t = {:.6g}, step {}", restart_path.string(), solver.time(),
                  solver.steps());
    }
    out.start(solver);
    log.print("stable time step {:.6g}", solver.stable_dt());
    if (!opt.resume) {
        out.sample(solver, 0.0, relaxation ? std::optional<bool>(true) : std::nullopt);
        out.frame(solver, 0.0, solver.state().x);
    }

    Run run{model, opt, solver_now, separated, schedule, out, log, WallClock(wall_before), restart};
    std::vector<Vec3> last_good;  // relaxation: the positions before the failed load level
    RunEnd end;
    try {
        end = relaxation ? relax_load_levels(run, last_good) : advance_in_time(run);
    } catch (const RunFailure& failure) {
        const ExplicitSolver& failed = *solver_now;
        end = run_end(1, std::string("failed: ") + failure.what());
        // The positions of a failed state that are no longer finite give way to those before
        // the failed step, which the solver keeps as x_prev, or before the load level (one
        // choice for every rank: each writes its piece of the last frame).
        const std::vector<Vec3>& x = failed.state().x;
        const bool finite = comm.max(all_finite(x) ? 0L : 1L) == 0;
        out.failure(failed, failure.what(),
                    finite       ? x
                    : relaxation ? last_good
                                 : failed.state().x_prev);
    }
    const ExplicitSolver& last = *solver_now;
    if (!relaxation) report_mass_scaling(model, last.added_mass(), "by the end of the run", log);
    end.wall_seconds = run.clock.seconds();
    end.threads = threads;
    end.ranks = comm.size();
    const PlasticStrainPeaks plastic_strain = plastic_strain_peaks(last);  // collective
    if (result_files.summary != nullptr)
        result_files.summary->set_plastic_strain_peaks(plastic_strain);
    out.finish(last, end);
    return end.exit_code;
}

}  // namespace fpmshell
