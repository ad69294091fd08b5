// summary.json observer; the keys are listed in model-format.md.
#include "fpmshell/driver/summary_file.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "fpmshell/driver/output_fields.hpp"
#include "fpmshell/failure/element_erosion.hpp"
#include "fpmshell/io/summary_json.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

namespace {

JsonValue peaks_json(const Model& model, const HistoryFile& history) {
    JsonValue peaks = JsonValue::object();
    const std::vector<HistoryFile::Peak> all = history.peaks();
    for (std::size_t i = 0; i < all.size(); ++i) {
        JsonValue p = JsonValue::object();
        p.set("value", all[i].value);
        p.set("time", all[i].time);
        peaks.set(model.output.histories[i].name, p);
    }
    return peaks;
}

/// Peak equivalent plastic strain per surface (it never decreases, so the last state holds
/// it), averaged over the in-plane points of an element like the VTU fields.
JsonValue plastic_strain_json(const PlasticStrainPeaks& peaks) {
    JsonValue plastic = JsonValue::object();
    const char* names[] = {"bottom", "middle", "top"};
    for (std::size_t s = 0; s < 3; ++s) plastic.set(std::string("max_") + names[s], peaks.peak[s]);
    const int best = peaks.surface();
    const auto b = static_cast<std::size_t>(best < 0 ? 0 : best);
    plastic.set("max", best < 0 ? 0.0 : peaks.peak[b]);
    plastic.set("element", best < 0 ? Index{0} : peaks.element[b] + 1);
    plastic.set("surface", std::string(best < 0 ? "none" : names[b]));
    return plastic;
}

JsonValue contact_json(const ContactStatistics& c, double wall) {
    JsonValue cj = JsonValue::object();
    cj.set("max_penetration", c.max_penetration);
    cj.set("max_penetration_ratio", c.max_penetration_ratio);  // / slave thickness
    cj.set("max_penetration_step", c.max_penetration_step);
    cj.set("max_penetration_particle", c.max_penetration_particle + 1);
    cj.set("max_penetration_element", c.max_penetration_element + 1);  // 0: a rigid body
    cj.set("max_active", c.max_active);
    cj.set("max_sweeps", c.max_sweeps);
    cj.set("unconverged_steps", c.unconverged_steps);
    cj.set("searches", c.searches);
    cj.set("held_penetrations", c.held_penetrations);
    cj.set("initial_penetrations", c.initial_penetrations);
    cj.set("seconds", c.seconds);
    cj.set("share_of_time_loop", wall > 0 ? c.seconds / wall : 0.0);
    return cj;
}

JsonValue rigid_bodies_json(const Model& model, const ExplicitSolver& solver) {
    JsonValue bodies = JsonValue::object();
    for (std::size_t b = 0; b < model.rigid_bodies.size(); ++b) {
        const RigidBodyState& st = solver.bodies()[b];
        JsonValue bj = JsonValue::object();
        JsonValue u = JsonValue::array(), v = JsonValue::array();
        for (int k = 0; k < 3; ++k) {
            u.push_back(st.u[k]);
            v.push_back(st.v[k]);
        }
        bj.set("displacement", u);
        bj.set("velocity", v);
        bodies.set(model.rigid_bodies[b].name, bj);
    }
    return bodies;
}

/// control.mass_scaling (§6.10): the target step and the mass added by the end of the run (at
/// set-up and during the run), in all and per section.
JsonValue mass_scaling_json(const Model& model, const AddedMass& added) {
    JsonValue mj = JsonValue::object();
    mj.set("time_step", model.control.mass_scaling.time_step);
    mj.set("added_mass", added.total_added());
    mj.set("physical_mass", added.total_physical());
    mj.set("added_mass_limit", model.control.mass_scaling.added_mass_limit);
    mj.set("added_kinetic_energy", added.kinetic_energy);  // eq. 6.10b, in the external work
    JsonValue sections = JsonValue::array();
    for (std::size_t s = 0; s < added.added.size(); ++s) {
        JsonValue sj = JsonValue::object();
        sj.set("section", static_cast<Index>(s));
        sj.set("added_mass", added.added[s]);
        sj.set("physical_mass", added.physical[s]);
        sections.push_back(sj);
    }
    mj.set("sections", sections);
    return mj;
}

}  // namespace

SummaryFile::SummaryFile(const Model& model, std::filesystem::path dir, const HistoryFile& history)
    : model_(model), dir_(std::move(dir)), history_(history) {}

void SummaryFile::finish(const ExplicitSolver& solver, const RunEnd& end) {
    const double wall = end.wall_seconds;
    JsonValue j = JsonValue::object();
    j.set("title", model_.title);
    j.set("particles", model_.n_particles());
    j.set("elements", model_.n_elements());
    j.set("steps", solver.steps());
    j.set("end_time", solver.time());
    j.set("wall_seconds", wall);
    j.set("element_steps_per_second",
          wall > 0 ? static_cast<double>(solver.element_steps()) / wall : 0.0);
    j.set("threads", end.threads);
    j.set("ranks", end.ranks);
    j.set("energy_error", solver.energy().error());
    j.set("peaks", peaks_json(model_, history_));
    j.set("plastic_strain",
          plastic_strain_json(plastic_strain_ ? *plastic_strain_ : plastic_strain_peaks(solver)));
    j.set("plastic_work", solver.energy().plastic);
    if (const ContactStatistics* c = solver.contact_statistics())
        j.set("contact", contact_json(*c, wall));
    if (!model_.rigid_bodies.empty()) j.set("rigid_bodies", rigid_bodies_json(model_, solver));
    if (model_.control.mass_scaling.time_step > 0)
        j.set("mass_scaling", mass_scaling_json(model_, solver.added_mass()));
    if (model_can_erode(model_)) {  // theory.md §7.6
        j.set("eroded_elements", solver.eroded_elements());
        if (solver.eroded_elements() > 0) j.set("first_erosion_time", solver.first_erosion_time());
        j.set("eroded_internal", solver.energy().eroded_internal);
    }
    if (solver.elements().separates()) {  // theory.md §7.7
        j.set("open_sides", static_cast<Index>(solver.open_sides()));
        j.set("split_particles", solver.split_particles());
        j.set("separations", static_cast<Index>(solver.separation_history().splits.size()));
        j.set("particles_at_end", solver.model().n_particles());
    }
    if (const NodalRigidBodies& welds = solver.nodal_rigid_bodies(); welds.has_failing_welds()) {
        j.set("failed_welds", welds.failed_welds());  // theory.md eq. 6.11-13
        if (welds.failed_welds() > 0)
            j.set("first_weld_failure_time", welds.first_weld_failure_time());
    }
    if (const TiedSurfaces* tied = solver.tied_surfaces()) {  // theory.md §6.12
        j.set("tied_particles", tied->tied());
        j.set("untied_particles", tied->untied());
        j.set("broken_ties", tied->broken());
    }
    j.set("version", FPMSHELL_VERSION);
    j.set("exit_reason", end.reason);
    write_json_file(dir_ / "summary.json", j);
}

}  // namespace fpmshell
