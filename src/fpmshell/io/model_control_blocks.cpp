// The `control`, `damping` and `output` blocks of the model file (see model_blocks.hpp).
#include <string>
#include <utility>
#include <vector>

#include "fpmshell/io/model_blocks.hpp"
#include "fpmshell/io/model_names.hpp"

namespace fpmshell {
namespace {

/// `rigid_<body>_<ux|uy|uz|vx|vy|vz|ax|ay|az|force_x|force_y|force_z>`.
void rigid_quantity(const Model& model, const YamlValue& q, HistoryRequest& req) {
    static const std::vector<std::pair<std::string, Quantity>> parts = {
        {"ux", Quantity::RigidUx},          {"uy", Quantity::RigidUy},
        {"uz", Quantity::RigidUz},          {"vx", Quantity::RigidVx},
        {"vy", Quantity::RigidVy},          {"vz", Quantity::RigidVz},
        {"ax", Quantity::RigidAx},          {"ay", Quantity::RigidAy},
        {"az", Quantity::RigidAz},          {"force_x", Quantity::RigidForceX},
        {"force_y", Quantity::RigidForceY}, {"force_z", Quantity::RigidForceZ}};
    const std::string qn = q.name();
    std::vector<std::string> bodies;
    for (std::size_t b = 0; b < model.rigid_bodies.size(); ++b) {
        const std::string prefix = "rigid_" + model.rigid_bodies[b].name + "_";
        bodies.push_back(model.rigid_bodies[b].name);
        if (qn.rfind(prefix, 0) != 0) continue;
        const std::string rest = qn.substr(prefix.size());
        for (const auto& [name, quantity] : parts)
            if (name == rest) {
                req.quantity = quantity;
                req.body = static_cast<Index>(b);
                return;
            }
        q.fail("unknown rigid-body quantity '" + rest + "' of body '" + model.rigid_bodies[b].name +
               "'; expected rigid_" + model.rigid_bodies[b].name +
               "_ followed by ux, uy, uz, vx, vy, vz, ax, ay, az, force_x, force_y or force_z");
    }
    q.fail(bodies.empty() ? "'" + qn + "' names a rigid body, but the model has no rigid_bodies"
                          : "'" + qn + "' names no rigid body of the model; the bodies are " +
                                join_names(bodies) + " (e.g. rigid_" + bodies.front() + "_uz)");
}

/// `contact_<n>_force_<x|y|z>`: the contact force on the slaves of the n-th contact definition.
void contact_quantity(const Model& model, const YamlValue& q, HistoryRequest& req) {
    const std::string qn = q.name();
    const std::string expected =
        "expected contact_<n>_force_x, _y or _z, n from 1 to the number of contact definitions (" +
        std::to_string(model.contacts.size()) + ")";
    const auto underscore = qn.find('_', 8);
    const std::string number =
        qn.substr(8, underscore == std::string::npos ? std::string::npos : underscore - 8);
    const std::string rest = underscore == std::string::npos ? "" : qn.substr(underscore + 1);
    if (number.empty() || number.size() > 6 ||
        number.find_first_not_of("0123456789") != std::string::npos)
        q.fail("'" + qn + "': " + expected);
    const std::size_t n = std::stoul(number);
    if (n < 1 || n > model.contacts.size())
        q.fail("'" + qn + "' names contact definition " + number + ", but the model has " +
               std::to_string(model.contacts.size()) + "; " + expected);
    if (rest != "force_x" && rest != "force_y" && rest != "force_z")
        q.fail("'" + qn + "': " + expected);
    req.quantity = rest == "force_x"   ? Quantity::ContactForceX
                   : rest == "force_y" ? Quantity::ContactForceY
                                       : Quantity::ContactForceZ;
    req.contact = static_cast<Index>(n - 1);
}

/// control.mass_scaling: {time_step: > 0, added_mass_limit: >= 0, during_run}, dynamic runs
/// only.
void read_mass_scaling(const YamlValue& v, Control& c) {
    const YamlMap m = v.map({"time_step", "added_mass_limit", "during_run"});
    c.mass_scaling.time_step =
        m.at("time_step", "the target time step of the run, a number > 0").positive();
    c.mass_scaling.added_mass_limit =
        m.non_negative_or("added_mass_limit", c.mass_scaling.added_mass_limit);
    c.mass_scaling.during_run = m.choice_or("during_run", {"true", "false"}, "true") == "true";
    if (c.mode == SolutionMode::Relaxation)
        v.fail(
            "mass scaling is for dynamic runs; relaxation (control.mode) has no time to "
            "scale");
}

/// `minimum_time_step: {factor | time_step, erode}` (LS-DYNA's DTMIN and ERODE).
void read_minimum_time_step(const YamlValue& v, Control& c) {
    const YamlMap m = v.map({"factor", "time_step", "erode"});
    MinimumTimeStep& floor = c.minimum_time_step;
    const auto factor = m.find("factor");
    const auto step = m.find("time_step");
    if (factor.has_value() == step.has_value())
        v.fail("needs one of factor (a fraction of the run's first step) and time_step");
    if (factor) {
        floor.factor = factor->positive();
        if (floor.factor >= 1)
            factor->fail("must be below 1 (a fraction of the run's first step), got " +
                         factor->describe());
    } else {
        floor.time_step = step->positive();
    }
    floor.erode = m.choice_or("erode", {"true", "false"}, "false") == "true";
    if (c.mode == SolutionMode::Relaxation)
        v.fail("is for dynamic runs; relaxation (control.mode) has no time step to watch");
}

}  // namespace

void read_control(const YamlValue& v, Model& model) {
    const YamlMap m =
        v.map({"end_time", "time_step_scale", "mode", "tolerance", "bending", "energy_error_limit",
               "max_relaxation_iterations", "thickness_update", "membrane", "end_when_body_stops",
               "rotary_inertia", "mass_scaling", "minimum_time_step"});
    Control& c = model.control;
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
    c.membrane = m.choice_or("membrane", {"cst", "smoothed"}, "cst") == "smoothed"
                     ? MembraneKernel::Smoothed
                     : MembraneKernel::Cst;
    if (const auto s = m.find("max_relaxation_iterations"))
        c.max_relaxation_iterations = static_cast<long>(s->integer(1, 1'000'000'000'000LL));
    const std::string inertia =
        m.choice_or("rotary_inertia", {"belytschko", "abaqus", "radioss"}, "belytschko");
    c.rotary_inertia = inertia == "abaqus"    ? RotaryInertia::Abaqus
                       : inertia == "radioss" ? RotaryInertia::Radioss
                                              : RotaryInertia::Belytschko;
    if (const auto s = m.find("mass_scaling")) read_mass_scaling(*s, c);
    if (const auto s = m.find("minimum_time_step")) read_minimum_time_step(*s, c);
}

void read_end_when_body_stops(const YamlValue& v, Model& model) {
    const auto key = v.open_map("control settings").find("end_when_body_stops");
    if (!key) return;
    model.control.end_body = named_rigid_body(model, *key);
    const RigidBody& b = model.rigid_bodies[static_cast<std::size_t>(model.control.end_body)];
    if (b.fixed)
        key->fail("the rigid body '" + b.name +
                  "' is fixed: it keeps its velocity and never stops");
    if (b.velocity.squaredNorm() == 0)
        key->fail("the rigid body '" + b.name +
                  "' has no initial velocity, so it has stopped already; "
                  "give it a `velocity` or remove end_when_body_stops");
    if (model.control.mode == SolutionMode::Relaxation)
        key->fail("end_when_body_stops needs mode: dynamic");
}

void read_damping(const YamlValue& v, Model& model) {
    const YamlMap m = v.map({"mass", "stiffness"});
    model.damping.mass = m.non_negative_or("mass", 0);
    model.damping.stiffness = m.non_negative_or("stiffness", 0);
}

void read_output(const std::optional<YamlValue>& v, Model& model) {
    OutputControl& o = model.output;
    o.every = model.control.end_time / 200;
    o.fields_every = model.control.end_time / 20;
    if (!v) return;
    const YamlMap m =
        v->map({"every", "fields_every", "fields_encoding", "fields_compression", "histories"});
    o.every = m.non_negative_or("every", o.every);
    o.fields_every = m.non_negative_or("fields_every", o.fields_every);
    const std::string encoding = m.choice_or("fields_encoding", {"raw", "base64", "ascii"}, "raw");
    o.fields_encoding = encoding == "base64"  ? FieldsEncoding::Base64
                        : encoding == "ascii" ? FieldsEncoding::Ascii
                                              : FieldsEncoding::Raw;
    o.fields_zlib = m.choice_or("fields_compression", {"none", "zlib"}, "none") == "zlib";
    if (o.fields_zlib && o.fields_encoding != FieldsEncoding::Raw)
        m.at("fields_compression")
            .fail("zlib compression needs fields_encoding: raw (VTK compresses appended data)");
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
        {"force_z", Quantity::ForceZ},
        {"pressure", Quantity::Pressure},
        {"eroded_elements", Quantity::ErodedElements}};  // the model's (read apart below)
    std::vector<std::string> quantity_names;
    for (const auto& [name, q] : quantities) quantity_names.push_back(name);
    static const std::vector<std::pair<std::string, Reduce>> reductions = {
        {"sum", Reduce::Sum},
        {"max", Reduce::Max},
        {"min", Reduce::Min},
        {"mean", Reduce::Mean},
        {"mass_mean", Reduce::MassMean}};

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
            rigid_quantity(model, q, req);
            if (const auto n = r.find("nodes"))
                n->fail("a rigid-body quantity belongs to the body, not to nodes; remove `nodes`");
            if (const auto red = r.find("reduce"))
                red->fail("a rigid-body quantity is one value; remove `reduce`");
            o.histories.push_back(req);
            continue;
        }
        if (qn == "eroded_elements") {  // theory.md §7.6: the count over the run
            req.quantity = Quantity::ErodedElements;
            req.model_wide = true;
            for (const char* key : {"nodes", "reduce"})
                if (const auto k = r.find(key))
                    k->fail("eroded_elements is one count of the whole model; remove `" +
                            std::string(key) + "`");
            o.histories.push_back(req);
            continue;
        }
        if (qn.rfind("contact_", 0) == 0) {
            contact_quantity(model, q, req);
            if (const auto n = r.find("nodes"))
                n->fail(
                    "a contact quantity belongs to the contact definition, not to nodes; "
                    "remove `nodes`");
            if (const auto red = r.find("reduce"))
                red->fail("a contact quantity is one value; remove `reduce`");
            o.histories.push_back(req);
            continue;
        }
        const YamlValue nodes = r.at("nodes", "a node set name");
        req.nodes = named_node_set(model, nodes);
        const std::string chosen = q.choice(quantity_names);
        for (const auto& [n, quantity] : quantities)
            if (n == chosen) req.quantity = quantity;
        if (const auto red = r.find("reduce")) {
            const std::string rn = red->choice({"sum", "max", "min", "mean", "mass_mean"});
            for (const auto& [n, reduce] : reductions)
                if (n == rn) req.reduce = reduce;
        } else if (req.nodes.size() > 1) {
            nodes.fail("the set '" + nodes.name() + "' has " + std::to_string(req.nodes.size()) +
                       " nodes, so the history needs `reduce: sum`, max, min, mean or mass_mean");
        }
        o.histories.push_back(req);
    }
}

}  // namespace fpmshell
