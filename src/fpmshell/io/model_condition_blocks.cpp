// The `curves`, `boundary`, `loads` and `initial_conditions` blocks of the model file (see
// model_blocks.hpp).
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "fpmshell/io/model_blocks.hpp"
#include "fpmshell/io/model_names.hpp"
#include "fpmshell/loads/blast/blast_yaml.hpp"

namespace fpmshell {

void read_curves(const YamlValue& v, Model& model) {
    const YamlMap all = v.open_map("curve names to [[time, factor], ...] lists");
    for (const auto& [name, def] : all.entries()) {
        Curve c;
        c.name = name;
        const auto points = def.list("[time, factor] pairs");
        if (points.empty())
            def.fail("a curve needs at least one [time, factor] pair, e.g. [[0, 0], [1, 1]]");
        std::string previous_time;
        for (const YamlValue& p : points) {
            const auto tf = p.list_of(2, "two numbers [time, factor]", "a pair [time, factor]");
            const Real t = tf[0].real();
            const Real f = tf[1].real();
            if (!c.points.empty() && !(t > c.points.back().first))
                tf[0].fail("the times of a curve must increase strictly, but time " +
                           tf[0].describe() + " follows time " + previous_time);
            previous_time = tf[0].describe();
            c.points.emplace_back(t, f);
        }
        model.curves.push_back(c);
    }
}

std::array<bool, 6> fixed_dofs(const YamlValue& fix) {
    static const std::vector<std::string> dofs = {"ux", "uy", "uz", "rx", "ry", "rz"};
    std::array<bool, 6> fixed{};
    if (fix.is_scalar()) {
        if (fix.choice({"all"}) == "all") fixed.fill(true);
        return fixed;
    }
    const auto list = fix.list("degrees of freedom");
    if (list.empty()) fix.fail("expected `all` or a non-empty list of ux, uy, uz, rx, ry, rz");
    for (const YamlValue& d : list) {
        const std::string name = d.choice(dofs);
        fixed[static_cast<std::size_t>(std::find(dofs.begin(), dofs.end(), name) - dofs.begin())] =
            true;
    }
    return fixed;
}

void read_boundary(const YamlValue& v, Model& model) {
    // the particles of the sections of rigid materials: a rigid body moves as a whole
    std::vector<std::string> rigid_material(model.nodes.size());
    for (std::size_t e = 0; e < model.triangles.size(); ++e) {
        const Section& sec = model.sections[static_cast<std::size_t>(model.element_section[e])];
        const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
        if (mat.rigid)
            for (const Index p : model.triangles[e])
                rigid_material[static_cast<std::size_t>(p)] = mat.name;
    }
    for (const YamlValue& item : v.list("boundary conditions")) {
        const YamlMap m = item.map({"nodes", "rigid_body", "fix", "symmetry", "prescribe"});
        BoundaryCondition bc;
        if (m.count({"nodes", "rigid_body"}) != 1)
            item.fail(
                "a boundary condition needs exactly one of nodes (a node set) or rigid_body (the "
                "elements of a rigid part)");
        if (const auto body = m.find("rigid_body")) {
            // the rigid body of these elements, held or driven as a whole (theory.md eq. 6.11-7)
            bc.rigid_elements = named_element_set(model, *body);
            for (const Index e : bc.rigid_elements) {
                const Section& sec =
                    model.sections[static_cast<std::size_t>(model.element_section[e])];
                if (!model.materials[static_cast<std::size_t>(sec.material)].rigid)
                    body->fail("element " + std::to_string(e + 1) +
                               " is not of a rigid material (rigid_body names the elements of "
                               "a rigid part)");
            }
        } else {
            const YamlValue nodes = m.at("nodes", "a node set name");
            bc.nodes = named_node_set(model, nodes);
            for (const Index p : bc.nodes)
                if (const std::string& name = rigid_material[static_cast<std::size_t>(p)];
                    !name.empty())
                    nodes.fail("particle " + std::to_string(p + 1) +
                               " belongs to a section of the rigid material '" + name +
                               "' (a rigid body moves as a whole: constrain none of its "
                               "particles, or give the body's motion with rigid_body)");
        }
        if (m.count({"fix", "symmetry", "prescribe"}) == 0)
            item.fail(
                "a boundary condition needs at least one of fix, symmetry or "
                "prescribe");
        if (const auto fix = m.find("fix")) bc.fixed = fixed_dofs(*fix);
        if (const auto sym = m.find("symmetry")) {
            const std::string axis = sym->choice({"x", "y", "z"});
            // Plane normal to `axis`: no normal displacement, no rotation about the two
            // in-plane axes.
            const std::size_t a = axis == "x" ? 0 : axis == "y" ? 1 : 2;
            bc.fixed[a] = true;
            for (std::size_t r = 0; r < 3; ++r)
                if (r != a) bc.fixed[3 + r] = true;
        }
        if (const auto pre = m.find("prescribe")) {
            const YamlMap p = pre->map({"displacement", "velocity", "acceleration",
                                        "angular_velocity", "curve", "components"});
            if (p.count({"displacement", "velocity", "acceleration", "angular_velocity"}) != 1)
                pre->fail(
                    "needs exactly one of displacement, velocity, acceleration or "
                    "angular_velocity (a list of 3 numbers), optionally with a curve");
            if (const auto acc = p.find("acceleration")) {
                if (model.control.mode == SolutionMode::Relaxation)
                    acc->fail(
                        "an acceleration is a dynamic drive: control.mode relaxation takes a "
                        "displacement or a velocity");
                bc.prescribed = PrescribedKind::Acceleration;
                bc.value = acc->vec3();
            } else if (const auto d = p.find("displacement")) {
                bc.prescribed = PrescribedKind::Displacement;
                bc.value = d->vec3();
            } else if (const auto vel = p.find("velocity")) {
                bc.prescribed = PrescribedKind::Velocity;
                bc.value = vel->vec3();
            } else {
                bc.prescribed = PrescribedKind::AngularVelocity;
                bc.value = p.at("angular_velocity").vec3();
            }
            bc.curve = optional_curve(model, p);
            if (const auto comps = p.find("components")) {
                // a rigid body's angular velocity may be prescribed about some axes only
                const bool rotations = bc.prescribed == PrescribedKind::AngularVelocity;
                if (rotations && bc.rigid_elements.empty())
                    comps->fail(
                        "an angular velocity is prescribed about all three axes; "
                        "`components` is for a displacement or a velocity (or a rigid_body's "
                        "rotation axes rx, ry, rz)");
                const auto list =
                    comps->list(rotations ? "rotation axes" : "translation components");
                if (list.empty())
                    comps->fail(rotations ? "expected a non-empty list of rx, ry, rz"
                                          : "expected a non-empty list of ux, uy, uz");
                bc.components = {false, false, false};
                for (const YamlValue& c : list) {
                    const std::string name =
                        rotations ? c.choice({"rx", "ry", "rz"}) : c.choice({"ux", "uy", "uz"});
                    bc.components[static_cast<std::size_t>(name[1] - 'x')] = true;
                }
            }
        }
        model.boundary.push_back(bc);
    }
}

void read_loads(const YamlValue& v, Model& model) {
    for (const YamlValue& item : v.list("loads")) {
        if (item.is_map() && item.open_map("a load")
                                     .at("type", "pressure, force, moment, gravity or blast")
                                     .text() == "blast") {  // §6.13, its own keys (loads/blast/)
            model.blast_loads.push_back(read_blast_load(item, model));
            continue;
        }
        const YamlMap m = item.map({"type", "nodes", "elements", "value", "curve"});
        const std::string type = m.at("type", "pressure, force, moment, gravity or blast")
                                     .choice({"pressure", "force", "moment", "gravity", "blast"});
        Load load;
        if (type == "gravity") {  // theory.md eq. 6.7-4
            load.type = LoadType::Gravity;
            if (const auto n = m.find("nodes"))
                n->fail(
                    "gravity acts on the particles of elements: use `elements: SET`, or nothing "
                    "for every particle");
            if (const auto e = m.find("elements")) {
                for (const Index el : named_element_set(model, *e))
                    for (const Index p : model.triangles[static_cast<std::size_t>(el)])
                        load.nodes.push_back(p);
                std::sort(load.nodes.begin(), load.nodes.end());
                load.nodes.erase(std::unique(load.nodes.begin(), load.nodes.end()),
                                 load.nodes.end());
            } else {
                load.nodes.resize(model.nodes.size());
                std::iota(load.nodes.begin(), load.nodes.end(), Index{0});
            }
            load.vector = m.at("value", "the acceleration [x, y, z]").vec3();
        } else if (type == "pressure") {
            load.type = LoadType::Pressure;
            if (const auto n = m.find("nodes"))
                n->fail("a pressure acts on elements: use `elements: SET` instead of `nodes`");
            load.elements = named_element_set(model, m.at("elements", "an element set name"));
            load.pressure = m.at("value", "the pressure, a number").real();
        } else {
            load.type = type == "force" ? LoadType::Force : LoadType::Moment;
            if (const auto e = m.find("elements"))
                e->fail("a " + type +
                        " acts on each node of a set: use `nodes: SET` instead "
                        "of `elements`");
            load.nodes = named_node_set(model, m.at("nodes", "a node set name"));
            load.vector = m.at("value", "a list of 3 numbers [x, y, z]").vec3();
        }
        load.curve = optional_curve(model, m);
        model.loads.push_back(load);
    }
}

void read_moves(const YamlValue& v, Model& model) {
    for (const YamlValue& item : v.list("moves")) {
        const YamlMap m = item.map({"nodes", "by"});
        const auto& nodes = named_node_set(model, m.at("nodes", "a node set name"));
        const Vec3 by = m.at("by", "the translation [dx, dy, dz]").vec3();
        for (const Index p : nodes) model.nodes[static_cast<std::size_t>(p)] += by;
    }
}

void read_initial_conditions(const YamlValue& v, Model& model) {
    for (const YamlValue& item : v.list("initial conditions")) {
        const YamlMap m =
            item.map({"nodes", "velocity", "angular_velocity", "normal_velocity", "rotation"});
        InitialVelocity ic;
        ic.nodes = named_node_set(model, m.at("nodes", "a node set name"));
        if (m.count({"velocity", "angular_velocity", "normal_velocity", "rotation"}) == 0)
            item.fail(
                "an initial condition needs `velocity: [vx, vy, vz]`, `normal_velocity: v` "
                "(along the surface normal), `angular_velocity: [wx, wy, wz]` and/or `rotation: "
                "{centre, angular_velocity}`");
        if (const auto vel = m.find("velocity")) ic.velocity = vel->vec3();
        if (const auto vn = m.find("normal_velocity")) ic.normal_velocity = vn->real();
        if (const auto w = m.find("angular_velocity")) ic.angular_velocity = w->vec3();
        if (const auto r = m.find("rotation")) {  // a rigid rotation about an axis
            if (const auto w = m.find("angular_velocity"))
                w->fail(
                    "give the particles' spin either as angular_velocity or through "
                    "`rotation`, not both");
            const YamlMap rot = r->map({"centre", "angular_velocity"});
            const YamlValue centre =
                rot.at("centre", "a point [x, y, z] of the rotation axis, or `mass`");
            if (centre.is_scalar()) {  // the centre of mass of the set's particles
                (void)centre.choice({"mass"});
                ic.spin_about_mass_centre = true;
            } else {
                ic.spin_centre = centre.vec3();
            }
            ic.spin =
                rot.at("angular_velocity", "the rotation vector [wx, wy, wz] (rad/time)").vec3();
        }
        model.initial_conditions.push_back(ic);
    }
}

namespace {

/// A `constraints` entry of type tied: nodes (a set or a list of sets), elements (the faces),
/// tolerance (theory.md §6.12).
void read_tied_surface(const YamlValue& item, Model& model) {
    const YamlMap m = item.map({"type", "nodes", "elements", "tolerance", "failure"});
    TiedSurface t;
    const YamlValue nodes = m.at("nodes", "a node set name or a list of them");
    for (const YamlValue& name :
         nodes.is_list() ? nodes.list("node set names") : std::vector<YamlValue>{nodes}) {
        const auto& set = named_node_set(model, name);
        t.nodes.insert(t.nodes.end(), set.begin(), set.end());
    }
    const YamlValue elements = m.at("elements", "an element set name or a list of them");
    for (const YamlValue& name : elements.is_list() ? elements.list("element set names")
                                                    : std::vector<YamlValue>{elements}) {
        const auto& set = named_element_set(model, name);
        t.elements.insert(t.elements.end(), set.begin(), set.end());
    }
    for (auto* list : {&t.nodes, &t.elements}) {
        std::sort(list->begin(), list->end());
        list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    if (t.nodes.empty()) nodes.fail("a tied constraint needs at least one particle");
    if (t.elements.empty()) elements.fail("a tied constraint needs at least one element");
    t.tolerance = m.non_negative_or("tolerance", 0.0);
    if (const auto f = m.find("failure")) {
        // a tiebreak (eq. 6.12-2): the forces at which a tie lets go, and the exponents
        const YamlMap fm = f->map({"normal_force", "shear_force", "normal_stress", "shear_stress",
                                   "normal_exponent", "shear_exponent"});
        t.normal_force = fm.non_negative_or("normal_force", 0.0);
        t.shear_force = fm.non_negative_or("shear_force", 0.0);
        t.normal_stress = fm.non_negative_or("normal_stress", 0.0);  // eq. 6.12-3
        t.shear_stress = fm.non_negative_or("shear_stress", 0.0);
        t.normal_exponent = fm.positive_or("normal_exponent", 2.0);
        t.shear_exponent = fm.positive_or("shear_exponent", 2.0);
        const bool forces = fm.count({"normal_force", "shear_force"}) > 0;
        const bool stresses = fm.count({"normal_stress", "shear_stress"}) > 0;
        if (forces && stresses)
            f->fail(
                "give the tiebreak's limits as forces (normal_force, shear_force) or as "
                "stresses (normal_stress, shear_stress), not both");
        if (t.normal_force == 0 && t.shear_force == 0 && t.normal_stress == 0 &&
            t.shear_stress == 0)
            f->fail(
                "a tiebreak needs normal_force or shear_force > 0 (the force at which a tie "
                "lets go), or normal_stress or shear_stress > 0");
    }
    model.tied_surfaces.push_back(std::move(t));
}

/// A spot weld's `failure` (theory.md eqs. 6.11-13, 6.11-14): the forces at which it lets go,
/// their exponents, a time.
void read_weld_failure(const YamlValue& f, NodalRigidBody& body) {
    const YamlMap fm = f.map({"normal_force", "shear_force", "normal_exponent", "shear_exponent",
                              "time", "plastic_strain"});
    NodalRigidBody::Failure& w = body.failure;
    w.normal_force = fm.non_negative_or("normal_force", 0.0);
    w.shear_force = fm.non_negative_or("shear_force", 0.0);
    w.normal_exponent = fm.positive_or("normal_exponent", 2.0);
    w.shear_exponent = fm.positive_or("shear_exponent", 2.0);
    if (fm.count({"time"}) > 0) w.time = fm.non_negative_or("time", 0.0);
    if (fm.count({"plastic_strain"}) > 0) w.plastic_strain = fm.positive_or("plastic_strain", 1.0);
    if (!body.can_fail())
        f.fail(
            "a spot weld's failure needs normal_force or shear_force > 0 (the force at which it "
            "lets go), a time or a plastic_strain");
}

}  // namespace

void read_constraints(const YamlValue& v, Model& model) {
    // the particles that have a boundary condition: a rigid body's motion is that of all its
    // particles, so one fixed or driven particle would have to move the others
    std::vector<std::uint8_t> bounded(model.nodes.size(), 0);
    for (const BoundaryCondition& bc : model.boundary)
        for (const Index p : bc.nodes) bounded[static_cast<std::size_t>(p)] = 1;
    for (const YamlValue& item : v.list("constraints")) {
        const YamlMap any = item.open_map("a constraint");
        const std::string type =
            any.at("type", "rigid (the nodes move as one rigid body) or tied (to faces)")
                .choice({"rigid", "tied"});
        if (type == "tied") {
            read_tied_surface(item, model);
            continue;
        }
        const YamlMap m = item.map({"type", "nodes", "failure"});
        const YamlValue nodes = m.at("nodes", "a node set name or a list of them");
        NodalRigidBody body;
        if (nodes.is_list()) {
            // several sets: their union (LS-DYNA's *CONSTRAINED_RIGID_BODIES, _EXTRA_NODES)
            const auto names = nodes.list("node set names");
            if (names.empty()) nodes.fail("expected a node set name or a non-empty list of them");
            for (const YamlValue& name : names) {
                const auto& set = named_node_set(model, name);
                body.nodes.insert(body.nodes.end(), set.begin(), set.end());
            }
            std::sort(body.nodes.begin(), body.nodes.end());
            body.nodes.erase(std::unique(body.nodes.begin(), body.nodes.end()), body.nodes.end());
        } else {
            body.nodes = named_node_set(model, nodes);
        }
        if (body.nodes.size() < 2)
            nodes.fail("a rigid body needs at least two particles, the set" +
                       std::string(nodes.is_list() ? "s have " : " '" + nodes.text() + "' has ") +
                       std::to_string(body.nodes.size()));
        for (const Index p : body.nodes)
            if (bounded[static_cast<std::size_t>(p)])
                nodes.fail("particle " + std::to_string(p + 1) +
                           " of the rigid body also has a boundary condition (a rigid body "
                           "moves as a whole: constrain none of its particles)");
        if (const auto f = m.find("failure")) read_weld_failure(*f, body);
        model.nodal_rigid_bodies.push_back(std::move(body));
    }
}

}  // namespace fpmshell
