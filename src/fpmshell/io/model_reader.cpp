// YAML model file -> validated Model (see model_reader.hpp and model-format.md).
// One function per top-level key; each checks its own keys, types and ranges.
#include "fpmshell/io/model_reader.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <vector>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/mesh_input.hpp"
#include "fpmshell/io/overrides.hpp"
#include "fpmshell/io/set_builder.hpp"
#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/model/node_thickness.hpp"

namespace fpmshell {
namespace {

constexpr std::uintmax_t k_max_model_file_bytes = 64U << 20U;

const std::vector<std::string> k_top_keys = {"title",        "mesh",     "sets",
                                             "materials",    "sections", "boundary",
                                             "curves",       "loads",    "initial_conditions",
                                             "rigid_bodies", "contact",  "damping",
                                             "control",      "output"};

std::string not_supported(const std::string& what) {
    return what + " is not supported yet in this version of fpmshell";
}

std::vector<std::string> names_of(const std::map<std::string, std::vector<Index>>& sets) {
    std::vector<std::string> names;
    for (const auto& [name, members] : sets) names.push_back(name);
    return names;
}

/// Everything the readers of the individual blocks share.
class Reader {
public:
    explicit Reader(Model& model) : model_(model) {}

    const std::vector<Index>& node_set(const YamlValue& v) const {
        const std::string name = v.name();
        const auto it = model_.node_sets.find(name);
        if (it == model_.node_sets.end()) {
            const auto names = names_of(model_.node_sets);
            v.fail("unknown node set '" + name + "'" + did_you_mean(name, names) +
                   "; the model defines the node sets " + join_names(names));
        }
        return it->second;
    }

    /// Index of the rigid body that v names (contact bodies, control.end_when_body_stops).
    Index rigid_body(const YamlValue& v) const {
        std::vector<std::string> names;
        for (std::size_t b = 0; b < model_.rigid_bodies.size(); ++b) {
            if (model_.rigid_bodies[b].name == v.name()) return static_cast<Index>(b);
            names.push_back(model_.rigid_bodies[b].name);
        }
        if (names.empty()) v.fail("the model has no rigid_bodies; define the body first");
        v.fail("unknown rigid body '" + v.name() + "'" + did_you_mean(v.name(), names) + "; the bodies are " +
               join_names(names));
    }

    const std::vector<Index>& element_set(const YamlValue& v) const {
        const std::string name = v.name();
        const auto it = model_.element_sets.find(name);
        const auto names = names_of(model_.element_sets);
        if (it == model_.element_sets.end()) {
            if (model_.node_sets.count(name) != 0)
                v.fail("'" + name +
                       "' is a node set, not an element set; the model defines the "
                       "element sets " +
                       join_names(names));
            v.fail("unknown element set '" + name + "'" + did_you_mean(name, names) +
                   "; the model defines the element sets " + join_names(names));
        }
        if (it->second.empty())
            v.fail("the element set '" + name +
                   "' contains no element (a near/plane set holds only the elements whose three "
                   "nodes are all in it); use a box set or a mesh set");
        return it->second;
    }

    Index curve(const YamlValue& v) const {
        const std::string name = v.name();
        std::vector<std::string> names;
        for (std::size_t i = 0; i < model_.curves.size(); ++i) {
            if (model_.curves[i].name == name) return static_cast<Index>(i);
            names.push_back(model_.curves[i].name);
        }
        v.fail("unknown curve '" + name + "'" + did_you_mean(name, names) +
               (names.empty() ? std::string("; the model defines no curves (add them under "
                                            "`curves`)")
                              : "; the model defines the curves " + join_names(names)));
    }

    Index material(const YamlValue& v) const {
        const std::string name = v.name();
        std::vector<std::string> names;
        for (std::size_t i = 0; i < model_.materials.size(); ++i) {
            if (model_.materials[i].name == name) return static_cast<Index>(i);
            names.push_back(model_.materials[i].name);
        }
        v.fail("unknown material '" + name + "'" + did_you_mean(name, names) +
               "; the model defines the materials " + join_names(names));
    }

    Index optional_curve(const YamlMap& m) const {
        const auto c = m.find("curve");
        return c ? curve(*c) : -1;
    }

    void control(const YamlValue& v) {
        const YamlMap m = v.map({"end_time", "time_step_scale", "mode", "tolerance", "bending",
                                 "energy_error_limit", "max_relaxation_iterations", "thickness_update",
                                 "membrane", "end_when_body_stops"});
        Control& c = model_.control;
        c.end_time = m.at("end_time", "the duration of the run, a number > 0").positive();
        if (const auto s = m.find("time_step_scale")) {
            c.time_step_scale = s->positive();
            if (c.time_step_scale > 1)
                s->fail("must be in (0, 1] (a fraction of the critical time step), got " +
                        s->describe());
        }
        c.mode = m.choice_or("mode", {"dynamic", "relaxation"}, "dynamic") == "relaxation"
                     ? SolutionMode::Relaxation
                     : SolutionMode::Dynamic;
        c.tolerance = m.positive_or("tolerance", c.tolerance);
        c.bending = m.choice_or("bending", {"bciz", "dkt"}, "dkt") == "dkt" ? BendingKernel::Dkt
                                                                             : BendingKernel::Bciz;
        c.energy_error_limit = m.positive_or("energy_error_limit", c.energy_error_limit);
        c.thickness_update = m.choice_or("thickness_update", {"true", "false"}, "false") == "true";
        c.membrane = m.choice_or("membrane", {"cst", "smoothed"}, "cst") == "smoothed" ? MembraneKernel::Smoothed
                                                                                     : MembraneKernel::Cst;
        if (const auto s = m.find("max_relaxation_iterations"))
            c.max_relaxation_iterations = static_cast<long>(s->integer(1, 1'000'000'000'000LL));
        if (const auto b = m.find("end_when_body_stops")) end_body_key_.emplace(*b);  // bodies come later
    }

    /// control.end_when_body_stops, once the rigid bodies are known: a moving body with a
    /// velocity, in a dynamic run.
    void end_body() {
        if (!end_body_key_) return;
        const YamlValue& key = *end_body_key_;
        model_.control.end_body = rigid_body(key);
        const RigidBody& b = model_.rigid_bodies[static_cast<std::size_t>(model_.control.end_body)];
        if (b.fixed)
            key.fail("the rigid body '" + b.name + "' is fixed: it keeps its velocity and never stops");
        if (b.velocity.squaredNorm() == 0)
            key.fail("the rigid body '" + b.name + "' has no initial velocity, so it has stopped already; "
                     "give it a `velocity` or remove end_when_body_stops");
        if (model_.control.mode == SolutionMode::Relaxation)
            key.fail("end_when_body_stops needs mode: dynamic");
    }

    void materials(const YamlValue& v) {
        const YamlMap all = v.open_map("material names to material definitions");
        if (all.entries().empty())
            v.fail(
                "at least one material is required, e.g. steel: {type: elastic, density: "
                "7.8e-9, youngs_modulus: 210000, poisson_ratio: 0.3}");
        for (const auto& [name, def] : all.entries()) {
            if (!def.is_map() && !def.is_null())
                def.fail(
                    "expected a map of material constants such as {type: elastic, density: "
                    "..., youngs_modulus: ..., poisson_ratio: ...}, got " +
                    def.describe());
            const YamlMap any = def.open_map("material constants");
            const YamlValue type = any.at("type", "elastic");
            const std::string t = type.choice({"elastic", "j2_plastic", "johnson_cook"});
            std::vector<std::string> keys{"type", "density", "youngs_modulus", "poisson_ratio"};
            if (t == "elastic") {
                for (const auto& [key, value] : any.entries())
                    for (const char* plastic :
                         {"yield_stress", "tangent_modulus", "hardening_mix", "cowper_symonds", "A", "B",
                          "n", "C", "reference_strain_rate", "m", "room_temperature", "melt_temperature"})
                        if (key == plastic)
                            value.fail(
                                "belongs to plastic materials (type: j2_plastic or johnson_cook); "
                                "remove it or change the type");
            } else if (t == "j2_plastic") {
                keys.insert(keys.end(), {"yield_stress", "tangent_modulus", "hardening_mix", "cowper_symonds"});
            } else {
                for (const char* thermal : {"m", "room_temperature", "melt_temperature"})
                    if (const auto th = any.find(thermal))
                        th->fail(not_supported("the thermal softening term of Johnson-Cook") +
                                "; remove m, room_temperature and melt_temperature");
                if (const auto cs = any.find("cowper_symonds"))
                    cs->fail("is a rate factor for j2_plastic; johnson_cook has its own rate term C");
                keys.insert(keys.end(), {"A", "B", "n", "C", "reference_strain_rate", "hardening_mix"});
            }
            const YamlMap m = def.map(keys);
            Material mat;
            mat.name = name;
            mat.type = t == "elastic" ? MaterialType::Elastic
                     : t == "j2_plastic" ? MaterialType::J2Plastic
                                         : MaterialType::JohnsonCook;
            mat.density = m.at("density", "a number > 0").positive();
            mat.youngs_modulus = m.at("youngs_modulus", "a number > 0").positive();
            const YamlValue nu = m.at("poisson_ratio", "a number in (-1, 0.5)");
            mat.poisson_ratio = nu.real();
            if (!(mat.poisson_ratio > -1 && mat.poisson_ratio < 0.5))
                nu.fail("must be greater than -1 and less than 0.5, got " + nu.describe());
            if (mat.plastic()) {
                if (const auto mix = m.find("hardening_mix")) {
                    mat.hardening_mix = mix->real();
                    if (!(mat.hardening_mix >= 0 && mat.hardening_mix <= 1))
                        mix->fail("must be in [0, 1] (1 isotropic, 0 kinematic hardening), got " + mix->describe());
                }
            }
            if (mat.type == MaterialType::J2Plastic) {
                mat.yield_stress = m.at("yield_stress", "the initial yield stress, a number > 0").positive();
                if (const auto et = m.find("tangent_modulus")) {
                    mat.tangent_modulus = et->non_negative();
                    if (!(mat.tangent_modulus < mat.youngs_modulus))
                        et->fail("must be below youngs_modulus (the slope of the bilinear curve past "
                                 "yield; 0 = perfectly plastic), got " + et->describe());
                }
                if (const auto cs = m.find("cowper_symonds")) {
                    const YamlMap c = cs->map({"D", "q"});
                    mat.cowper_symonds = true;
                    mat.cs_d = c.at("D", "the Cowper-Symonds rate constant D [1/time], a number > 0").positive();
                    mat.cs_q = c.at("q", "the Cowper-Symonds exponent q, a number > 0").positive();
                }
            }
            if (mat.type == MaterialType::JohnsonCook) {
                mat.jc_a = m.at("A", "the Johnson-Cook yield stress A, a number > 0").positive();
                mat.jc_b = m.at("B", "the Johnson-Cook hardening modulus B, a number >= 0").non_negative();
                mat.jc_n = m.at("n", "the Johnson-Cook hardening exponent n, a number > 0").positive();
                mat.jc_c = m.non_negative_or("C", 0.0);
                mat.reference_strain_rate = m.positive_or("reference_strain_rate", 1.0);
            }
            model_.materials.push_back(mat);
        }
    }

    void sections(const YamlValue& v) {
        const auto items = v.list("sections");
        if (items.empty())
            v.fail(
                "at least one section is required, e.g. - {elements: all, material: steel, "
                "thickness: 1.0}");
        model_.element_section.assign(model_.triangles.size(), -1);
        for (const YamlValue& item : items) {
            const YamlMap m = item.map(
                {"elements", "material", "thickness", "thickness_points", "inplane_points"});
            const auto& elements = element_set(m.at("elements", "an element set name such as all"));
            Section s;
            s.material = material(m.at("material", "a material name"));
            if (model_.materials[static_cast<std::size_t>(s.material)].plastic()) {
                s.thickness_points = 5;  // Lobatto: the surfaces yield first (theory.md §7.5)
                s.inplane_points = 7;
            }
            s.thickness = m.at("thickness", "a number > 0").positive();
            if (const auto tp = m.find("thickness_points")) {
                const long long n = tp->integer(2, 5);
                if (n == 4)
                    tp->fail(
                        "expected 2 (Gauss), 3 or 5 (Lobatto) points through the "
                        "thickness, got 4");
                s.thickness_points = static_cast<int>(n);
            }
            if (const auto ip = m.find("inplane_points")) {
                const long long n = ip->integer(3, 7);
                if (n != 3 && n != 7)
                    ip->fail("expected 3 or 7 in-plane integration points, got " + ip->describe());
                s.inplane_points = static_cast<int>(n);
            }
            const auto index = static_cast<Index>(model_.sections.size());
            model_.sections.push_back(s);
            for (const Index e : elements)
                model_.element_section[static_cast<std::size_t>(e)] = index;
        }
        const auto missing =
            std::find(model_.element_section.begin(), model_.element_section.end(), Index{-1});
        if (missing != model_.element_section.end()) {
            const auto e = missing - model_.element_section.begin();
            const auto n_missing = std::count(missing, model_.element_section.end(), Index{-1});
            v.fail("element " + std::to_string(e + 1) + " (and " + std::to_string(n_missing - 1) +
                   " more) has no section; every element needs one, e.g. start with an entry "
                   "for `elements: all`");
        }
    }

    void curves(const YamlValue& v) {
        const YamlMap all = v.open_map("curve names to [[time, factor], ...] lists");
        for (const auto& [name, def] : all.entries()) {
            Curve c;
            c.name = name;
            const auto points = def.list("[time, factor] pairs");
            if (points.empty())
                def.fail("a curve needs at least one [time, factor] pair, e.g. [[0, 0], [1, 1]]");
            std::string previous_time;
            for (const YamlValue& p : points) {
                const auto tf = p.list("two numbers [time, factor]");
                if (tf.size() != 2)
                    p.fail("expected a pair [time, factor], got " +
                           (p.is_list() ? "a list of " + std::to_string(tf.size()) + " items"
                                        : p.describe()));
                const Real t = tf[0].real();
                const Real f = tf[1].real();
                if (!c.points.empty() && !(t > c.points.back().first))
                    tf[0].fail("the times of a curve must increase strictly, but time " +
                               tf[0].describe() + " follows time " + previous_time);
                previous_time = tf[0].describe();
                c.points.emplace_back(t, f);
            }
            model_.curves.push_back(c);
        }
    }

    void boundary(const YamlValue& v) {
        static const std::vector<std::string> dofs = {"ux", "uy", "uz", "rx", "ry", "rz"};
        for (const YamlValue& item : v.list("boundary conditions")) {
            const YamlMap m = item.map({"nodes", "fix", "symmetry", "prescribe"});
            BoundaryCondition bc;
            bc.nodes = node_set(m.at("nodes", "a node set name"));
            if (m.count({"fix", "symmetry", "prescribe"}) == 0)
                item.fail(
                    "a boundary condition needs at least one of fix, symmetry or "
                    "prescribe");
            if (const auto fix = m.find("fix")) {
                if (fix->is_scalar()) {
                    if (fix->choice({"all"}) == "all") bc.fixed.fill(true);
                } else {
                    const auto list = fix->list("degrees of freedom");
                    if (list.empty())
                        fix->fail("expected `all` or a non-empty list of ux, uy, uz, rx, ry, rz");
                    for (const YamlValue& d : list) {
                        const std::string name = d.choice(dofs);
                        const auto k = std::find(dofs.begin(), dofs.end(), name) - dofs.begin();
                        bc.fixed[static_cast<std::size_t>(k)] = true;
                    }
                }
            }
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
                const YamlMap p =
                    pre->map({"displacement", "velocity", "angular_velocity", "curve"});
                if (p.count({"displacement", "velocity", "angular_velocity"}) != 1)
                    pre->fail(
                        "needs exactly one of displacement, velocity or angular_velocity "
                        "(a list of 3 numbers), optionally with a curve");
                if (const auto d = p.find("displacement")) {
                    bc.prescribed = PrescribedKind::Displacement;
                    bc.value = d->vec3();
                } else if (const auto vel = p.find("velocity")) {
                    bc.prescribed = PrescribedKind::Velocity;
                    bc.value = vel->vec3();
                } else {
                    bc.prescribed = PrescribedKind::AngularVelocity;
                    bc.value = p.at("angular_velocity").vec3();
                }
                bc.curve = optional_curve(p);
            }
            model_.boundary.push_back(bc);
        }
    }

    void loads(const YamlValue& v) {
        for (const YamlValue& item : v.list("loads")) {
            const YamlMap m = item.map({"type", "nodes", "elements", "value", "curve"});
            const std::string type =
                m.at("type", "pressure, force or moment").choice({"pressure", "force", "moment"});
            Load load;
            if (type == "pressure") {
                load.type = LoadType::Pressure;
                if (const auto n = m.find("nodes"))
                    n->fail("a pressure acts on elements: use `elements: SET` instead of `nodes`");
                load.elements = element_set(m.at("elements", "an element set name"));
                load.pressure = m.at("value", "the pressure, a number").real();
            } else {
                load.type = type == "force" ? LoadType::Force : LoadType::Moment;
                if (const auto e = m.find("elements"))
                    e->fail("a " + type +
                            " acts on each node of a set: use `nodes: SET` instead "
                            "of `elements`");
                load.nodes = node_set(m.at("nodes", "a node set name"));
                load.vector = m.at("value", "a list of 3 numbers [x, y, z]").vec3();
            }
            load.curve = optional_curve(m);
            model_.loads.push_back(load);
        }
    }

    void initial_conditions(const YamlValue& v) {
        for (const YamlValue& item : v.list("initial conditions")) {
            const YamlMap m = item.map({"nodes", "velocity", "angular_velocity", "normal_velocity"});
            InitialVelocity ic;
            ic.nodes = node_set(m.at("nodes", "a node set name"));
            if (m.count({"velocity", "angular_velocity", "normal_velocity"}) == 0)
                item.fail(
                    "an initial condition needs `velocity: [vx, vy, vz]`, `normal_velocity: v` "
                    "(along the surface normal) and/or `angular_velocity: [wx, wy, wz]`");
            if (const auto vel = m.find("velocity")) ic.velocity = vel->vec3();
            if (const auto vn = m.find("normal_velocity")) ic.normal_velocity = vn->real();
            if (const auto w = m.find("angular_velocity")) ic.angular_velocity = w->vec3();
            model_.initial_conditions.push_back(ic);
        }
    }

    void damping(const YamlValue& v) {
        const YamlMap m = v.map({"mass", "stiffness"});
        model_.damping.mass = m.non_negative_or("mass", 0);
        model_.damping.stiffness = m.non_negative_or("stiffness", 0);
    }

    void output(const std::optional<YamlValue>& v) {
        OutputControl& o = model_.output;
        o.every = model_.control.end_time / 200;
        o.fields_every = model_.control.end_time / 20;
        if (!v) return;
        const YamlMap m = v->map({"every", "fields_every", "histories"});
        o.every = m.non_negative_or("every", o.every);
        o.fields_every = m.non_negative_or("fields_every", o.fields_every);
        const auto h = m.find("histories");
        if (!h) return;
        static const std::vector<std::pair<std::string, Quantity>> quantities = {
            {"ux", Quantity::Ux},
            {"uy", Quantity::Uy},
            {"uz", Quantity::Uz},
            {"umag", Quantity::Umag},
            {"vx", Quantity::Vx},
            {"vy", Quantity::Vy},
            {"vz", Quantity::Vz},
            {"ax", Quantity::Ax},
            {"ay", Quantity::Ay},
            {"az", Quantity::Az},
            {"rx", Quantity::Rx},
            {"ry", Quantity::Ry},
            {"rz", Quantity::Rz},
            {"reaction_x", Quantity::ReactionX},
            {"reaction_y", Quantity::ReactionY},
            {"reaction_z", Quantity::ReactionZ},
            {"reaction_mx", Quantity::ReactionMx},  // constraint moments (the particle's own,
            {"reaction_my", Quantity::ReactionMy},  // not about an origin)
            {"reaction_mz", Quantity::ReactionMz},
            {"force_x", Quantity::ForceX},
            {"force_y", Quantity::ForceY},
            {"force_z", Quantity::ForceZ}};
        std::vector<std::string> quantity_names;
        for (const auto& [name, q] : quantities) quantity_names.push_back(name);
        static const std::vector<std::pair<std::string, Reduce>> reductions = {
            {"sum", Reduce::Sum},
            {"max", Reduce::Max},
            {"min", Reduce::Min},
            {"mean", Reduce::Mean}};

        for (const YamlValue& item : h->list("history requests")) {
            const YamlMap r = item.map({"name", "nodes", "quantity", "reduce"});
            HistoryRequest req;
            const YamlValue name = r.at("name", "a column name for history.csv");
            req.name = name.name();
            if (req.name.find_first_of(",\"\n\r") != std::string::npos)
                name.fail(
                    "a history name must not contain commas, quotes or line breaks (it "
                    "becomes a column of history.csv), got " +
                    name.describe());
            if (req.name == "time")
                name.fail("'time' is the first column of history.csv already; choose another name");
            for (const auto& other : o.histories)
                if (other.name == req.name)
                    name.fail("the history name '" + req.name +
                              "' is used twice; names must be "
                              "unique");
            const YamlValue q = r.at("quantity", "one of " + join_names(quantity_names));
            const std::string qn = q.name();
            if (qn.rfind("rigid_", 0) == 0) {
                rigid_quantity(q, req);
                if (const auto n = r.find("nodes"))
                    n->fail("a rigid-body quantity belongs to the body, not to nodes; remove `nodes`");
                if (const auto red = r.find("reduce"))
                    red->fail("a rigid-body quantity is one value; remove `reduce`");
                o.histories.push_back(req);
                continue;
            }
            const YamlValue nodes = r.at("nodes", "a node set name");
            req.nodes = node_set(nodes);
            const std::string chosen = q.choice(quantity_names);
            for (const auto& [n, quantity] : quantities)
                if (n == chosen) req.quantity = quantity;
            if (const auto red = r.find("reduce")) {
                const std::string rn = red->choice({"sum", "max", "min", "mean"});
                for (const auto& [n, reduce] : reductions)
                    if (n == rn) req.reduce = reduce;
            } else if (req.nodes.size() > 1) {
                nodes.fail("the set '" + nodes.name() + "' has " +
                           std::to_string(req.nodes.size()) +
                           " nodes, so the history needs `reduce: sum`, max, min or mean");
            }
            o.histories.push_back(req);
        }
    }

    /// `rigid_<body>_<ux|uy|uz|vx|vy|vz|ax|ay|az|force_x|force_y|force_z>`.
    void rigid_quantity(const YamlValue& q, HistoryRequest& req) const {
        static const std::vector<std::pair<std::string, Quantity>> parts = {
            {"ux", Quantity::RigidUx},          {"uy", Quantity::RigidUy},
            {"uz", Quantity::RigidUz},          {"vx", Quantity::RigidVx},
            {"vy", Quantity::RigidVy},          {"vz", Quantity::RigidVz},
            {"ax", Quantity::RigidAx},          {"ay", Quantity::RigidAy},
            {"az", Quantity::RigidAz},          {"force_x", Quantity::RigidForceX},
            {"force_y", Quantity::RigidForceY}, {"force_z", Quantity::RigidForceZ}};
        const std::string qn = q.name();
        std::vector<std::string> bodies;
        for (std::size_t b = 0; b < model_.rigid_bodies.size(); ++b) {
            const std::string prefix = "rigid_" + model_.rigid_bodies[b].name + "_";
            bodies.push_back(model_.rigid_bodies[b].name);
            if (qn.rfind(prefix, 0) != 0) continue;
            const std::string rest = qn.substr(prefix.size());
            for (const auto& [name, quantity] : parts)
                if (name == rest) {
                    req.quantity = quantity;
                    req.body = static_cast<Index>(b);
                    return;
                }
            q.fail("unknown rigid-body quantity '" + rest + "' of body '" + model_.rigid_bodies[b].name +
                   "'; expected rigid_" + model_.rigid_bodies[b].name +
                   "_ followed by ux, uy, uz, vx, vy, vz, ax, ay, az, force_x, force_y or force_z");
        }
        q.fail(bodies.empty() ? "'" + qn + "' names a rigid body, but the model has no rigid_bodies"
                              : "'" + qn + "' names no rigid body of the model; the bodies are " +
                                    join_names(bodies) + " (e.g. rigid_" + bodies.front() + "_uz)");
    }

    void rigid_bodies(const YamlValue& v) {
        for (const YamlValue& item : v.list("rigid bodies")) {
            const YamlMap m = item.map({"name", "mass", "shape", "point", "normal", "velocity", "fixed"});
            RigidBody b;
            const YamlValue name = m.at("name", "a name for the body, used in contact and histories");
            b.name = name.name();
            if (b.name.empty() || b.name.find_first_of(",\"\n\r ") != std::string::npos)
                name.fail("a body name must be a single word without commas or quotes, got " + name.describe());
            for (const RigidBody& other : model_.rigid_bodies)
                if (other.name == b.name) name.fail("the rigid body '" + b.name + "' is defined twice");
            (void)m.choice_or("shape", {"plane"}, "plane");
            b.fixed = m.choice_or("fixed", {"true", "false"}, "false") == "true";
            if (b.fixed) {
                if (const auto mass = m.find("mass"))
                    mass->fail("a fixed body has infinite mass; remove `mass` or set `fixed: false`");
            } else {
                b.mass = m.at("mass", "the mass of the body, a number > 0 (or `fixed: true`)").positive();
            }
            b.point = m.at("point", "a point [x, y, z] of the plane face").vec3();
            const YamlValue normal = m.at("normal", "the face normal [nx, ny, nz], pointing towards the shell");
            b.normal = normal.vec3();
            if (!(b.normal.norm() > 0)) normal.fail("the normal must not be the zero vector");
            b.normal.normalize();
            if (const auto vel = m.find("velocity")) b.velocity = vel->vec3();
            model_.rigid_bodies.push_back(b);
        }
    }

    void contact(const YamlValue& v) {
        for (const YamlValue& item : v.list("contact definitions")) {
            const YamlMap any = item.open_map("contact settings");
            const std::string type = any.at("type", "self or rigid").choice({"self", "rigid"});
            ContactDefinition c;
            if (type == "self") {
                const YamlMap m = item.map({"type", "elements", "method", "exclusion_radius", "penalty_scale",
                                            "max_iterations"});
                c.type = ContactType::Self;
                c.elements = m.find("elements") ? element_set(*m.find("elements"))
                                                : model_.element_sets.at("all");
                c.exclusion_radius = m.non_negative_or("exclusion_radius", 0.0);
                common_contact(m, c);
            } else {
                const YamlMap m = item.map({"type", "body", "nodes", "method", "penalty_scale", "max_iterations"});
                c.type = ContactType::Rigid;
                c.body = rigid_body(m.at("body", "the name of a rigid body"));
                c.nodes = m.find("nodes") ? node_set(*m.find("nodes")) : model_.node_sets.at("all");
                common_contact(m, c);
                // A particle that starts inside the face (its half thickness included) would be
                // thrown out of it in one step.
                const RigidBody& rb = model_.rigid_bodies[static_cast<std::size_t>(c.body)];
                const std::vector<Real> h = node_thickness();
                for (const Index p : c.nodes) {
                    const auto up = static_cast<std::size_t>(p);
                    const Real behind = 0.5 * h[up] - rb.normal.dot(model_.nodes[up] - rb.point);
                    if (behind > 1e-9 * (1.0 + rb.point.norm()))
                        item.fail("particle " + std::to_string(p + 1) + " starts " + std::to_string(behind) +
                                  " inside the face of rigid body '" + rb.name +
                                  "' (a particle touches it with a ball of half its thickness; the face "
                                  "normal points towards the shell); move the body by that much or "
                                  "check the sign of its normal");
                }
            }
            model_.contacts.push_back(c);
        }
    }

private:
    /// Mean section thickness of the elements around each particle (contact offsets).
    [[nodiscard]] std::vector<Real> node_thickness() const {
        std::vector<Real> element_thickness(model_.triangles.size());
        for (std::size_t e = 0; e < element_thickness.size(); ++e)
            element_thickness[e] = model_.sections[static_cast<std::size_t>(model_.element_section[e])].thickness;
        return mean_node_thickness(model_.triangles, element_thickness, model_.nodes.size());
    }

    static void common_contact(const YamlMap& m, ContactDefinition& c) {
        c.method = m.choice_or("method", {"lagrange", "penalty"}, "lagrange") == "penalty"
                       ? ContactMethod::Penalty
                       : ContactMethod::LagrangeMultiplier;
        if (const auto s = m.find("penalty_scale")) {
            c.penalty_scale = s->positive();
            if (c.penalty_scale > 1)
                s->fail("must be in (0, 1]: stiffness = scale x pair mass / dt^2, and above 1 the "
                        "explicit step is unstable; got " + s->describe());
        }
        if (const auto it = m.find("max_iterations")) c.max_iterations = static_cast<int>(it->integer(1, 100000));
    }

    Model& model_;
    std::optional<YamlValue> end_body_key_;
};

YAML::Node load_yaml(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(input_error_text(path, 0, "",
                                          "cannot open the model file: it is a "
                                          "folder; expected a YAML file"));
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(input_error_text(
            path, 0, "", std::string("cannot open the model file (") + std::strerror(errno) + ")"));
    // Read at most the limit (+1 byte to notice more): also safe on pipes and devices.
    std::string content;
    std::vector<char> chunk(1U << 16U);
    while (in && content.size() <= k_max_model_file_bytes) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        content.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (content.size() > k_max_model_file_bytes)
        throw InputError(input_error_text(path, 0, "",
                                          "the model file is larger than 64 MiB; "
                                          "put big data in a mesh file"));
    try {
        return YAML::Load(content);
    } catch (const YAML::Exception& e) {
        const int line = e.mark.is_null() ? 0 : e.mark.line + 1;
        throw InputError(input_error_text(path, line, "",
                                          "the file is not valid YAML (" + e.msg +
                                              "); check the indentation, colons, quotes and "
                                              "brackets on this line and the lines just before"));
    }
}

}  // namespace

Model read_model(const std::string& path, const std::vector<std::string>& set_overrides) {
    YamlContext ctx(path);
    YAML::Node root = load_yaml(path);
    if (!root.IsDefined() || root.IsNull())
        throw InputError(input_error_text(path, 0, "",
                                          "the model file is empty; expected a map "
                                          "with at least mesh, materials, sections "
                                          "and control"));
    if (!root.IsMap())
        throw InputError(input_error_text(
            path, yaml_line(root), "",
            std::string("the top level of the model file must be a map of keys (title, mesh, "
                        "materials, ...), got ") +
                (root.IsSequence() ? "a list" : "a single value")));
    apply_overrides(root, set_overrides, ctx);

    Model model;
    model.source_file = path;
    const YamlMap top = YamlValue(ctx, root, "").map(k_top_keys);
    for (const char* required : {"mesh", "materials", "sections", "control"})
        if (!top.has(required))
            ctx.fail_at(1, required,
                        "is required but missing; a model needs mesh, materials, "
                        "sections and control");

    model.title = std::filesystem::path(path).stem().string();
    if (const auto t = top.find("title")) model.title = t->name();

    Reader reader(model);
    reader.control(top.at("control"));

    // Mesh and sets.
    const YamlValue mesh_key = top.at("mesh");
    MeshData mesh = read_mesh_block(mesh_key, std::filesystem::path(path).parent_path().string());
    if (mesh.node_sets.count("all") != 0 || mesh.element_sets.count("all") != 0)
        mesh_key.fail(
            "the mesh defines a set named 'all', which is reserved for the set of every "
            "node and element; rename it in the mesh file");
    if (const auto s = top.find("sets")) add_user_sets(*s, mesh);
    model.nodes = std::move(mesh.nodes);
    model.triangles = std::move(mesh.triangles);
    model.node_sets = std::move(mesh.node_sets);
    model.element_sets = std::move(mesh.element_sets);
    for (auto* sets : {&model.node_sets, &model.element_sets})
        for (auto& [name, members] : *sets) {
            std::sort(members.begin(), members.end());
            members.erase(std::unique(members.begin(), members.end()), members.end());
        }
    auto& all_nodes = model.node_sets["all"];
    for (Index i = 0; i < model.n_particles(); ++i) all_nodes.push_back(i);
    auto& all_elements = model.element_sets["all"];
    for (Index e = 0; e < model.n_elements(); ++e) all_elements.push_back(e);

    reader.materials(top.at("materials"));
    if (const auto c = top.find("curves")) reader.curves(*c);
    reader.sections(top.at("sections"));
    if (model.control.mode == SolutionMode::Relaxation) {
        // Dynamic relaxation jumps to each load level and oscillates about it: an elastic model
        // ends where it should, a plastic one keeps the plastic strain of the overshoot and of
        // the motion imposed in one step (a strip pulled in tension: 11 % of the right force).
        for (const Section& sec : model.sections) {
            const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
            if (mat.plastic())
                top.at("control").open_map("control settings").at("mode").fail(
                    "relaxation needs elastic materials, but material '" + mat.name +
                    "' is plastic: dynamic relaxation jumps to each load level, and a plastic "
                    "material would keep the strains of that jump; use mode: dynamic with a slow "
                    "load ramp (and some mass damping) for a quasi-static plastic path");
        }
    }
    if (const auto b = top.find("boundary")) reader.boundary(*b);
    if (const auto l = top.find("loads")) reader.loads(*l);
    if (const auto i = top.find("initial_conditions")) reader.initial_conditions(*i);
    if (const auto r = top.find("rigid_bodies"); r && !r->is_null()) reader.rigid_bodies(*r);
    reader.end_body();
    if (const auto c = top.find("contact"); c && !c->is_null()) {
        reader.contact(*c);
        if (model.control.mode == SolutionMode::Relaxation && !model.contacts.empty())
            c->fail("contact needs mode: dynamic (dynamic relaxation jumps between load levels, "
                    "and the contact forces of a jump are not those of equilibrium)");
    }
    if (const auto d = top.find("damping")) reader.damping(*d);
    reader.output(top.find("output"));
    return model;
}

}  // namespace fpmshell
