#include "fpmshell/driver/run_driver.hpp"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numeric>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/rotation.hpp"
#include "fpmshell/driver/history_sampler.hpp"
#include "fpmshell/driver/interrupt_guard.hpp"
#include "fpmshell/io/csv_table.hpp"
#include "fpmshell/io/field_frame.hpp"
#include "fpmshell/io/progress.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/io/run_directory.hpp"
#include "fpmshell/io/summary_json.hpp"
#include "fpmshell/io/vtu_writer.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {
namespace {

std::string version() { return FPMSHELL_VERSION; }

/// Field frame of the current state. positions_override: use these positions (last good
/// state after a failure) instead of the solver's.
/// Equivalent plastic strain of element e at the bottom (0), middle (1) or top (2) surface,
/// averaged over the in-plane points; with 2 Gauss points the middle is their mean.
Real surface_plastic_strain(const ShellElements& el, Index e, int which) {
    const int nk = el.thickness_points(e);
    if (which == 0) return el.plastic_strain(e, 0);
    if (which == 2) return el.plastic_strain(e, nk - 1);
    return nk % 2 == 1 ? el.plastic_strain(e, nk / 2)
                       : 0.5 * (el.plastic_strain(e, 0) + el.plastic_strain(e, nk - 1));
}

FieldFrame make_frame(const Model& model, const ExplicitSolver& solver, Real time,
                      const std::vector<Vec3>* positions_override = nullptr) {
    const ParticleState& s = solver.state();
    FieldFrame f;
    f.time = time;
    f.points = positions_override ? *positions_override : s.x;
    f.triangles = model.triangles;
    const std::size_t np = s.size(), ne = model.triangles.size();
    FieldArray disp{"displacement", 3, {}}, vel{"velocity", 3, {}}, rot{"rotation", 3, {}};
    for (std::size_t p = 0; p < np; ++p) {
        const Vec3 u = f.points[p] - s.x0[p];
        const Vec3 r = rotation_vector(s.rotation[p]);
        for (int c = 0; c < 3; ++c) {
            disp.values.push_back(u[c]);
            vel.values.push_back(s.v[p][c]);
            rot.values.push_back(r[c]);
        }
    }
    f.point_data = {disp, vel, rot};
    FieldArray nf{"membrane_force", 3, {}}, bm{"bending_moment", 3, {}}, th{"thickness", 1, {}};
    FieldArray ep_top{"plastic_strain_top", 1, {}}, ep_mid{"plastic_strain_middle", 1, {}},
        ep_bot{"plastic_strain_bottom", 1, {}};
    for (std::size_t e = 0; e < ne; ++e) {
        const Voigt3 n = solver.elements().membrane_force(static_cast<Index>(e));
        const Voigt3 m = solver.elements().bending_moment(static_cast<Index>(e));
        for (int c = 0; c < 3; ++c) {
            nf.values.push_back(n[c]);
            bm.values.push_back(m[c]);
        }
        th.values.push_back(solver.elements().thickness(static_cast<Index>(e)));
        const Index ie = static_cast<Index>(e);
        ep_bot.values.push_back(surface_plastic_strain(solver.elements(), ie, 0));
        ep_mid.values.push_back(surface_plastic_strain(solver.elements(), ie, 1));
        ep_top.values.push_back(surface_plastic_strain(solver.elements(), ie, 2));
    }
    f.cell_data = {nf, bm, th, ep_top, ep_mid, ep_bot};
    return f;
}

/// control.end_when_body_stops: the body no longer moves along its initial velocity (v^{n+1/2}).
bool body_has_stopped(const Model& model, const ExplicitSolver& solver) {
    if (model.control.end_body < 0) return false;
    const std::size_t b = static_cast<std::size_t>(model.control.end_body);
    return solver.bodies()[b].v.dot(model.rigid_bodies[b].velocity) <= 0;
}

bool all_finite(const std::vector<Vec3>& v) {
    return std::all_of(v.begin(), v.end(), [](const Vec3& a) { return a.allFinite(); });
}

struct Peak {
    Real value = 0;
    Real time = 0;
};

template <class Archive>
void transfer(Archive& ar, Peak& p) {
    ar(p.value, p.time);
}

/// Everything the run writes, kept together so that a failure can still flush it all.
class ResultWriter {
public:
    ResultWriter(const Model& model, const RunOptions& opt, bool relaxation)
        : model_(model), dir_(opt.output_dir), history_(history_header(model, relaxation)),
          energy_({"time", "kinetic", "internal", "plastic", "external_work", "damping",
                   "contact", "energy_error"}, 10),
          pvd_(dir_ / "fields.pvd"), peaks_(model.output.histories.size()) {}

    static std::vector<std::string> history_header(const Model& model, bool relaxation) {
        std::vector<std::string> h{"time"};
        for (const auto& r : model.output.histories) h.push_back(r.name);
        if (relaxation) h.push_back("converged");
        return h;
    }

    void sample(const ExplicitSolver& solver, Real time, std::optional<bool> converged = {}) {
        std::vector<Real> row{time};
        const std::vector<Real> vals = sample_histories(model_, solver);
        for (std::size_t i = 0; i < vals.size(); ++i) {
            row.push_back(vals[i]);
            if (std::abs(vals[i]) > std::abs(peaks_[i].value)) peaks_[i] = {vals[i], time};
        }
        if (converged) row.push_back(*converged ? 1.0 : 0.0);
        history_.add_row(row);
        const EnergyBalance& e = solver.energy();
        energy_.add_row({time, e.kinetic, e.internal, e.plastic, e.external_work, e.damping,
                         e.contact, e.error()});
    }

    void frame(const ExplicitSolver& solver, Real time, const std::vector<Vec3>* positions = nullptr) {
        const std::string rel = fmt::format("{}/frame_{:05d}.vtu", k_fields_folder, n_frames_++);
        write_vtu(dir_ / rel, make_frame(model_, solver, time, positions));
        pvd_.add(time, rel);
    }

    void flush() const {
        history_.flush(dir_ / "history.csv");
        energy_.flush(dir_ / "energy.csv");
    }

    void summary(const ExplicitSolver& solver, double wall, int threads, const std::string& reason) const {
        JsonValue j = JsonValue::object();
        j.set("title", model_.title);
        j.set("particles", model_.n_particles());
        j.set("elements", model_.n_elements());
        j.set("steps", solver.steps());
        j.set("end_time", solver.time());
        j.set("wall_seconds", wall);
        j.set("element_steps_per_second", wall > 0 ? static_cast<double>(solver.element_steps()) / wall : 0.0);
        j.set("threads", threads);
        j.set("energy_error", solver.energy().error());
        JsonValue peaks = JsonValue::object();
        for (std::size_t i = 0; i < peaks_.size(); ++i) {
            JsonValue p = JsonValue::object();
            p.set("value", peaks_[i].value);
            p.set("time", peaks_[i].time);
            peaks.set(model_.output.histories[i].name, p);
        }
        j.set("peaks", peaks);
        // Peak equivalent plastic strain (it never decreases, so the last state holds it), per
        // surface, averaged over the in-plane points of an element like the VTU fields.
        JsonValue plastic = JsonValue::object();
        const char* surfaces[] = {"bottom", "middle", "top"};
        Real best = 0;
        Index best_element = -1;
        std::string best_surface = "none";
        for (int which = 0; which < 3; ++which) {
            Real peak = 0;
            for (Index e = 0; e < model_.n_elements(); ++e) {
                const Real v = surface_plastic_strain(solver.elements(), e, which);
                peak = std::max(peak, v);
                if (v > best) {
                    best = v;
                    best_element = e;
                    best_surface = surfaces[which];
                }
            }
            plastic.set(std::string("max_") + surfaces[which], peak);
        }
        plastic.set("max", best);
        plastic.set("element", best_element >= 0 ? best_element + 1 : 0);
        plastic.set("surface", best_surface);
        j.set("plastic_strain", plastic);
        j.set("plastic_work", solver.energy().plastic);
        if (const ContactStatistics* c = solver.contact_statistics()) {
            JsonValue cj = JsonValue::object();
            cj.set("max_penetration", c->max_penetration);
            cj.set("max_penetration_ratio", c->max_penetration_ratio);  // / slave thickness
            cj.set("max_penetration_step", c->max_penetration_step);
            cj.set("max_penetration_particle", c->max_penetration_particle + 1);
            cj.set("max_penetration_element", c->max_penetration_element + 1);  // 0: a rigid body
            cj.set("max_active", c->max_active);
            cj.set("max_sweeps", c->max_sweeps);
            cj.set("unconverged_steps", c->unconverged_steps);
            cj.set("searches", c->searches);
            cj.set("held_penetrations", c->held_penetrations);
            cj.set("seconds", c->seconds);
            cj.set("share_of_time_loop", wall > 0 ? c->seconds / wall : 0.0);
            j.set("contact", cj);
        }
        if (!model_.rigid_bodies.empty()) {
            JsonValue bodies = JsonValue::object();
            for (std::size_t b = 0; b < model_.rigid_bodies.size(); ++b) {
                const RigidBodyState& st = solver.bodies()[b];
                JsonValue bj = JsonValue::object();
                JsonValue u = JsonValue::array(), v = JsonValue::array();
                for (int k = 0; k < 3; ++k) {
                    u.push_back(st.u[k]);
                    v.push_back(st.v[k]);
                }
                bj.set("displacement", u);
                bj.set("velocity", v);
                bodies.set(model_.rigid_bodies[b].name, bj);
            }
            j.set("rigid_bodies", bodies);
        }
        j.set("version", version());
        j.set("exit_reason", reason);
        write_json_file(dir_ / "summary.json", j);
    }

    /// Everything written so far, for a restart file: the rows of the histories, the frames
    /// listed in fields.pvd and the peaks.
    void save(RestartWriter& w) const {
        w.section("results");
        w(history_.rows(), energy_.rows(), pvd_.entries(), peaks_, n_frames_);
    }
    void load(RestartReader& r) {
        r.section("results");
        std::vector<std::vector<Real>> history, energy;
        std::vector<std::pair<Real, std::string>> frames;
        r(history, energy, frames, peaks_, n_frames_);
        if (peaks_.size() != model_.output.histories.size() ||
            std::any_of(history.begin(), history.end(),
                        [&](const std::vector<Real>& row) { return row.size() != history_.n_columns(); }))
            r.fail("restart file of a model with other output.histories");
        for (const auto& row : history) history_.add_row(row);
        for (const auto& row : energy) energy_.add_row(row);
        for (const auto& [time, file] : frames) pvd_.add(time, file);
    }
    [[nodiscard]] int frames() const { return n_frames_; }

private:
    const Model& model_;
    std::filesystem::path dir_;
    CsvTable history_, energy_;
    PvdSeries pvd_;
    std::vector<Peak> peaks_;
    int n_frames_ = 0;
};

}  // namespace

std::string model_summary(const Model& model) {
    const ExplicitSolver solver(model);
    std::string out;
    out += fmt::format("model      {}\n", model.source_file);
    out += fmt::format("title      {}\n", model.title);
    out += fmt::format("particles  {}\nelements   {}\n", model.n_particles(), model.n_elements());
    const auto& m = solver.state().mass;
    out += fmt::format("total mass {:.6g}\n", std::accumulate(m.begin(), m.end(), 0.0));
    out += "node sets ";
    for (const auto& [name, nodes] : model.node_sets) out += fmt::format(" {}({})", name, nodes.size());
    out += "\nelement sets";
    for (const auto& [name, elems] : model.element_sets) out += fmt::format(" {}({})", name, elems.size());
    for (const RigidBody& b : model.rigid_bodies)
        out += fmt::format("\nrigid body {}: plane through ({:.6g}, {:.6g}, {:.6g}), normal ({:.4g}, {:.4g}, {:.4g}), {}",
                           b.name, b.point.x(), b.point.y(), b.point.z(), b.normal.x(), b.normal.y(), b.normal.z(),
                           b.fixed ? std::string("fixed") : fmt::format("mass {:.6g}", b.mass));
    for (const ContactDefinition& c : model.contacts)
        out += c.type == ContactType::Self
                   ? fmt::format("\ncontact self over {} elements ({})", c.elements.size(),
                                 c.method == ContactMethod::Penalty ? "penalty" : "Lagrange multipliers")
                   : fmt::format("\ncontact of {} particles with rigid body {} ({})", c.nodes.size(),
                                 model.rigid_bodies[static_cast<std::size_t>(c.body)].name,
                                 c.method == ContactMethod::Penalty ? "penalty" : "Lagrange multipliers");
    const Real dt = solver.stable_dt();
    out += fmt::format("\nstable time step {:.6g} (time_step_scale {} x critical)\n", dt,
                       model.control.time_step_scale);
    if (model.control.mode == SolutionMode::Dynamic) {
        out += fmt::format("steps      about {:.0f} to end_time {}\n", std::ceil(model.control.end_time / dt),
                           model.control.end_time);
    } else {
        const Real every = model.output.every > 0 ? model.output.every : model.control.end_time;
        out += fmt::format("relaxation {:.0f} load levels to load parameter {}\n",
                           std::ceil(model.control.end_time / every - 1e-9), model.control.end_time);
    }
    return out;
}

int run_model(const Model& model, const RunOptions& opt) {
#ifdef _OPENMP
    if (opt.threads > 0) omp_set_num_threads(opt.threads);
    const int threads = omp_get_max_threads();
#else
    const int threads = 1;
#endif
    const bool relaxation = model.control.mode == SolutionMode::Relaxation;
    if (relaxation && (opt.resume || opt.restart_every > 0 || opt.stop_at_step > 0))
        throw InputError(input_error_text(model.source_file, 0, "control.mode",
                                          "restart files (--restart-every, --resume) are for dynamic runs, "
                                          "not for relaxation"));
    if (opt.resume)
        prepare_resume_directory(opt.output_dir, model.source_file, opt.overwrite);
    else
        prepare_run_directory(opt.output_dir, model.source_file, opt.overwrite);
    LogFile log(opt.output_dir / "log.txt", opt.echo);
    log.print("fpmshell {} — {}", version(), model.title);
    log.print("model {}, {} particles, {} elements, {} thread(s)", model.source_file,
              model.n_particles(), model.n_elements(), threads);

    ExplicitSolver solver(model);
    const Real end = model.control.end_time;
    const Real every = model.output.every;
    const Real fields_every = model.output.fields_every > 0 ? model.output.fields_every : end;
    Real next_row = every, next_frame = fields_every;
    double wall_before = 0;  // wall seconds of the earlier segments of a resumed run
    const std::filesystem::path restart_path = opt.output_dir / k_restart_file;
    // A restart file is checked against the model before the result writer exists: a refused
    // resume must leave the folder's fields.pvd (which the writer starts afresh) as it was.
    std::optional<RestartReader> restart;
    if (opt.resume) {
        restart.emplace(restart_path);
        solver.load(*restart);
        restart->section("driver");
        (*restart)(next_row, next_frame, wall_before);
    }
    ResultWriter out(model, opt, relaxation);
    if (restart) {
        out.load(*restart);
        restart->finish();
        remove_frames_from(opt.output_dir, out.frames());
        log.print("resumed from {} at t = {:.6g}, step {}", restart_path.string(), solver.time(), solver.steps());
    }
    Progress progress(end, opt.quiet, [&log](const std::string& s) { log.line(s); });
    log.set_progress(&progress);
    progress.resume_from(solver.time());
    log.print("stable time step {:.6g}", solver.stable_dt());

    if (!opt.resume) {
        out.sample(solver, 0.0, relaxation ? std::optional<bool>(true) : std::nullopt);
        out.frame(solver, 0.0);
    }
    out.flush();
    const auto wall0 = std::chrono::steady_clock::now();
    auto wall = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count(); };
    double last_restart = 0;
    // The state after a completed step, with everything written so far (README "restart files").
    auto write_restart = [&] {
        RestartWriter w;
        solver.save(w);
        w.section("driver");
        w(next_row, next_frame, wall_before + wall());
        out.save(w);
        w.save(restart_path);
        last_restart = wall();
    };
    std::string reason = "completed";
    int code = 0;
    // The positions a failed run writes when its own are no longer finite: in a dynamic run
    // those before the failed step, which the solver keeps as x_prev (no copy per step); in a
    // relaxation run those before the load level.
    std::vector<Vec3> last_good = solver.state().x;
    try {
        double last_flush = 0;
        if (!relaxation) {
            const InterruptGuard interrupts;
            while (solver.time() < end * (1 - 1e-12)) {
                // No sliver step at the end: when less than two steps remain, take two equal
                // ones (a last step ten times shorter than the one before jolts the leapfrog
                // kinetic energy and showed as a 0.1 % jump of the energy error).
                const Real remaining = end - solver.time();
                const Real last = solver.last_dt();
                const bool split = last > 0 && remaining > last * (1 + 1e-9) && remaining < 2 * last;
                solver.step(split ? 0.5 * remaining : remaining);
                const Real t = solver.time();
                const bool body_stopped = body_has_stopped(model, solver);
                const bool at_end = t >= end * (1 - 1e-12) || body_stopped;
                if (every <= 0 || t >= next_row * (1 - 1e-12) || at_end) {
                    out.sample(solver, t);
                    while (every > 0 && next_row <= t * (1 + 1e-12)) next_row += every;
                }
                if (t >= next_frame * (1 - 1e-12) || at_end) {
                    out.frame(solver, t);
                    while (next_frame <= t * (1 + 1e-12)) next_frame += fields_every;
                    out.flush();
                    last_flush = wall();
                } else if (wall() - last_flush > 2.0) {
                    out.flush();
                    last_flush = wall();
                }
                progress.update(t, solver.steps(), solver.last_dt(), solver.energy().error());
                const int interrupted = at_end ? 0 : InterruptGuard::received();
                const bool stop_here = (opt.stop_at_step > 0 && solver.steps() >= opt.stop_at_step && !at_end) ||
                                       interrupted != 0;
                if ((opt.restart_every > 0 && (wall() - last_restart >= opt.restart_every || at_end)) || stop_here) {
                    out.flush();
                    write_restart();
                }
                if (body_stopped) {
                    const std::string& name = model.rigid_bodies[static_cast<std::size_t>(model.control.end_body)].name;
                    progress.finish();
                    log.print("the rigid body '{}' has stopped at t = {:.6g} (control.end_when_body_stops): end of the run",
                              name, t);
                    reason = fmt::format("completed: rigid body {} stopped", name);
                    break;
                }
                if (interrupted != 0) {
                    progress.finish();
                    log.print("interrupted by {} after step {} at t = {:.6g}; the state is in {}: continue with "
                              "--resume", signal_name(interrupted), solver.steps(), t, restart_path.string());
                    reason = fmt::format("interrupted by {} at step {}: resume with --resume", signal_name(interrupted),
                                         solver.steps());
                    code = 128 + interrupted;  // the shell's convention for a process ended by a signal
                    break;
                }
                if (stop_here) {
                    progress.finish();
                    log.print("stopped after step {} at t = {:.6g}; continue with --resume from {}", solver.steps(), t,
                              restart_path.string());
                    reason = fmt::format("stopped at step {}: resume with --resume", solver.steps());
                    break;
                }
            }
    } else {
            const Real step = every > 0 ? every : end;
            const long levels = static_cast<long>(std::ceil(end / step - 1e-9));
            long unconverged = 0;
            for (long k = 1; k <= levels; ++k) {
                const Real t = std::min(end, static_cast<Real>(k) * step);
                last_good = solver.state().x;
                const ExplicitSolver::RelaxResult r = solver.relax(t);
                if (!r.converged) {
                    ++unconverged;
                    log.print("warning: load level {:.6g} did not converge in {} iterations "
                              "(residual ratio {:.3e} > tolerance {:.1e})",
                              t, r.iterations, r.residual_ratio, model.control.tolerance);
                }
                out.sample(solver, t, r.converged);
                if (t >= next_frame * (1 - 1e-12) || k == levels) {
                    out.frame(solver, t);
                    while (next_frame <= t * (1 + 1e-12)) next_frame += fields_every;
                }
                out.flush();
                progress.update(t, solver.steps(), solver.last_dt(), r.residual_ratio);
            }
            if (unconverged > 0)
                reason = fmt::format("completed; {} of {} load levels did not converge", unconverged, levels);
        }
    } catch (const RunFailure& failure) {
        progress.finish();
        log.print("error: {}", failure.what());
        log.print("the last good state (t = {:.6g}) is in the last frame of fields.pvd", solver.time());
        reason = std::string("failed: ") + failure.what();
        code = 1;
        const std::vector<Vec3>* pos =
            all_finite(solver.state().x) ? nullptr : relaxation ? &last_good : &solver.state().x_prev;
        try {
            out.frame(solver, solver.time(), pos);
        } catch (const std::exception& e) {
            log.print("could not write the last frame: {}", e.what());
        }
    }
    progress.finish();
    const double seconds = wall_before + wall();
    out.flush();
    out.summary(solver, seconds, threads, reason);
    log.print("{} after {} steps, t = {:.6g}, energy error {:.3f} %, {:.2f} s wall, {:.3g} element-steps/s",
              code == 0 ? "finished" : "stopped", solver.steps(), solver.time(),
              100 * solver.energy().error(), seconds,
              seconds > 0 ? static_cast<double>(solver.element_steps()) / seconds : 0.0);
    if (const ContactStatistics* c = solver.contact_statistics()) {
        log.print("contact: largest penetration {:.4g} ({:.2f} % of the thickness) at step {}, particle {}{}",
                  c->max_penetration, 100 * c->max_penetration_ratio, c->max_penetration_step,
                  c->max_penetration_particle + 1,
                  c->max_penetration_element >= 0 ? fmt::format(", element {}", c->max_penetration_element + 1)
                                                  : std::string(" (rigid body)"));
        log.print("contact: up to {} contact forces, up to {} sweeps ({} steps unconverged), {} pairs held "
                  "inside, {} searches, {:.2f} s ({:.1f} % of the time loop)",
                  c->max_active, c->max_sweeps, c->unconverged_steps, c->held_penetrations, c->searches, c->seconds,
                  seconds > 0 ? 100 * c->seconds / seconds : 0.0);
    }
    log.print("results in {}", opt.output_dir.string());
    return code;
}

}  // namespace fpmshell
