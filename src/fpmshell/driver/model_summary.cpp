// The summary of `fpmshell check`: the model as read, and its time step.
#include "fpmshell/driver/model_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "fpmshell/solver/explicit_solver.hpp"
#include "fpmshell/solver/nodal_rigid_bodies.hpp"

namespace fpmshell {

std::string model_summary(const Model& model) {
    const ExplicitSolver solver(model);
    std::string out;
    out += fmt::format("model      {}\n", model.source_file);
    out += fmt::format("title      {}\n", model.title);
    out += fmt::format("particles  {}\nelements   {}\n", model.n_particles(), model.n_elements());
    const auto& m = solver.state().mass;
    out += fmt::format("total mass {:.6g}\n", std::accumulate(m.begin(), m.end(), 0.0));
    if (!model.point_masses.empty()) {  // `masses`: in the total
        Real points = 0;
        std::vector<std::uint8_t> carries(model.nodes.size(), 0);
        for (const PointMass& pm : model.point_masses)
            for (std::size_t k = 0; k < pm.nodes.size(); ++k) {
                points += pm.masses[k];
                carries[static_cast<std::size_t>(pm.nodes[k])] = 1;
            }
        out += fmt::format("point masses {:.6g} on {} particles (in the total)\n", points,
                           std::count(carries.begin(), carries.end(), 1));
    }
    if (model.control.mass_scaling.time_step > 0)
        out += fmt::format("added mass {:.6g} (mass scaling to time step {:.6g}; in the total)\n",
                           solver.added_mass().total_added(), model.control.mass_scaling.time_step);
    out += "node sets ";
    for (const auto& [name, nodes] : model.node_sets)
        out += fmt::format(" {}({})", name, nodes.size());
    out += "\nelement sets";
    for (const auto& [name, elems] : model.element_sets)
        out += fmt::format(" {}({})", name, elems.size());
    for (const Material& mat : model.materials)
        out += fmt::format("\nmaterial {}: {}, density {:.6g}, E {:.6g}, nu {:.6g}", mat.name,
                           mat.law, mat.density, mat.youngs_modulus, mat.poisson_ratio);
    std::vector<std::size_t> section_elements(model.sections.size(), 0);
    for (const Index s : model.element_section) ++section_elements[static_cast<std::size_t>(s)];
    static constexpr const char* rule_names[] = {"", "Gauss", "Lobatto", "user"};
    for (std::size_t s = 0; s < model.sections.size(); ++s) {
        const Section& sec = model.sections[s];
        out += fmt::format(
            "\nsection {}: {} elements, material {}, thickness {:.6g}, {} {} x {} points", s,
            section_elements[s], model.materials[static_cast<std::size_t>(sec.material)].name,
            sec.thickness, sec.thickness_points,
            rule_names[static_cast<int>(
                sec.thickness_rule == ThicknessRule::ByCount
                    ? (sec.thickness_points <= 2 ? ThicknessRule::Gauss : ThicknessRule::Lobatto)
                    : sec.thickness_rule)],
            sec.inplane_points);
    }
    out += fmt::format("\nconditions {} boundary, {} loads, {} initial velocities, {} curves",
                       model.boundary.size(), model.loads.size() + model.blast_loads.size(),
                       model.initial_conditions.size(), model.curves.size());
    for (const BlastLoad& b : model.blast_loads) {  // §6.13, and where its shock arrives first
        const BlastFaces faces(b, model.nodes, model.triangles);
        std::size_t first = 0;
        for (std::size_t k = 1; k < faces.size(); ++k)
            if (faces.arrival(k) < faces.arrival(first)) first = k;
        out += fmt::format(
            "\nblast of {:.6g} TNT ({}) at ({:.6g}, {:.6g}, {:.6g}) on {} faces, detonated at "
            "{:.6g}; the shock reaches the first face at {:.6g} and its positive phase there lasts "
            "{:.6g} (model time units)",
            b.charge_mass, b.burst == BlastBurst::FreeAir ? "free air" : "surface burst",
            b.centre.x(), b.centre.y(), b.centre.z(), b.elements.size(), b.detonation_time,
            faces.size() ? b.detonation_time + faces.arrival(first) : 0.0,
            faces.size() ? faces.duration(first) : 0.0);
    }
    for (const RigidBody& b : model.rigid_bodies) {
        const std::string at =
            fmt::format("({:.6g}, {:.6g}, {:.6g})", b.point.x(), b.point.y(), b.point.z());
        std::string shape;
        if (b.shape == RigidShape::Plane)
            shape = fmt::format("plane through {}, normal ({:.4g}, {:.4g}, {:.4g}){}", at,
                                b.normal.x(), b.normal.y(), b.normal.z(),
                                b.size_l > 0 ? fmt::format(", {:.6g} x {:.6g}", b.size_l, b.size_m)
                                             : std::string());
        else if (b.shape == RigidShape::Sphere)
            shape = fmt::format("sphere of radius {:.6g} about {}", b.radius, at);
        else
            shape = fmt::format(
                "cylinder of radius {:.6g} on the axis ({:.4g}, {:.4g}, {:.4g}) "
                "from {}, {}",
                b.radius, b.axis.x(), b.axis.y(), b.axis.z(), at,
                b.length > 0 ? fmt::format("length {:.6g}", b.length) : std::string("infinite"));
        out += fmt::format("\nrigid body {}: {}, {}", b.name, shape,
                           b.fixed ? std::string("fixed") : fmt::format("mass {:.6g}", b.mass));
    }
    for (const ContactDefinition& c : model.contacts)
        out += c.type == ContactType::Self
                   ? fmt::format(
                         "\ncontact self over {} elements ({})", c.elements.size(),
                         c.method == ContactMethod::Penalty ? "penalty" : "Lagrange multipliers")
                   : fmt::format(
                         "\ncontact of {} particles with rigid body {} ({}{})", c.nodes.size(),
                         model.rigid_bodies[static_cast<std::size_t>(c.body)].name,
                         c.method == ContactMethod::Penalty ? "penalty" : "Lagrange multipliers",
                         c.friction == 0          ? std::string()
                         : std::isinf(c.friction) ? std::string(", no sliding")
                                                  : fmt::format(", friction {:.6g}", c.friction));
    if (const NodalRigidBodies bodies(model); !bodies.empty()) {
        std::size_t particles = 0;
        for (const auto& b : bodies.bodies()) particles += b.size();
        out += fmt::format("\nnodal rigid bodies: {} ({} particles)", bodies.bodies().size(),
                           particles);
    }
    if (const TiedSurfaces* tied = solver.tied_surfaces())
        out += fmt::format(
            "\ntied: {} particles to faces{}", tied->tied(),
            tied->untied() > 0
                ? fmt::format(", {} with no face within the tolerance (left free)", tied->untied())
                : std::string());
    const Real dt = solver.stable_dt();
    out += fmt::format("\nstable time step {:.6g} (time_step_scale {} x critical)\n", dt,
                       model.control.time_step_scale);
    if (solver.minimum_step() > 0)  // control.minimum_time_step
        out += fmt::format("minimum time step {:.6g}: {}\n", solver.minimum_step(),
                           model.control.minimum_time_step.erode
                               ? "the elements whose step falls below it erode"
                               : "the run stops if the step falls below it");
    if (model.control.mode == SolutionMode::Dynamic) {
        out += fmt::format("steps      about {:.0f} to end_time {}\n",
                           std::ceil(model.control.end_time / dt), model.control.end_time);
    } else {
        const Real every = model.output.every > 0 ? model.output.every : model.control.end_time;
        out +=
            fmt::format("relaxation {:.0f} load levels to load parameter {}\n",
                        std::ceil(model.control.end_time / every - 1e-9), model.control.end_time);
    }
    for (const std::string& note : model.notes) out += "note: " + note + "\n";
    return out;
}

}  // namespace fpmshell
