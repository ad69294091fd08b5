// The `rigid_bodies` and `contact` blocks of the model file (see model_blocks.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "fpmshell/io/model_blocks.hpp"
#include "fpmshell/io/model_names.hpp"
#include "fpmshell/model/node_thickness.hpp"
#include "fpmshell/model/rigid_face.hpp"

namespace fpmshell {
namespace {

/// Mean section thickness of the elements around each particle (contact offsets).
std::vector<Real> node_thickness(const Model& model) {
    std::vector<Real> element_thickness(model.triangles.size());
    for (std::size_t e = 0; e < element_thickness.size(); ++e)
        element_thickness[e] =
            model.sections[static_cast<std::size_t>(model.element_section[e])].thickness;
    return mean_node_thickness(model.triangles, element_thickness, model.nodes.size());
}

/// The keys that self and rigid contact share: method, penalty_scale, max_iterations.
void read_contact_method(const YamlMap& m, ContactDefinition& c) {
    c.method = m.choice_or("method", {"lagrange", "penalty"}, "lagrange") == "penalty"
                   ? ContactMethod::Penalty
                   : ContactMethod::LagrangeMultiplier;
    if (const auto s = m.find("penalty_scale")) {
        c.penalty_scale = s->positive();
        if (c.penalty_scale > 1)
            s->fail(
                "must be in (0, 1]: stiffness = scale x pair mass / dt^2, and above 1 the "
                "explicit step is unstable; got " +
                s->describe());
    }
    if (const auto it = m.find("max_iterations"))
        c.max_iterations = static_cast<int>(it->integer(1, 100000));
}

}  // namespace

namespace {

/// A unit vector from a non-zero one.
Vec3 unit_vector(const YamlValue& v, const char* what) {
    Vec3 u = v.vec3();
    if (!(u.norm() > 0)) v.fail(std::string("the ") + what + " must not be the zero vector");
    return u.normalized();
}

/// The geometry keys of each shape (model/rigid_face.hpp); a key of another shape is an error.
void read_shape(const YamlMap& m, const std::string& shape, RigidBody& b) {
    const std::vector<std::string> own =
        shape == "plane"    ? std::vector<std::string>{"normal", "edge", "size"}
        : shape == "sphere" ? std::vector<std::string>{"radius"}
                            : std::vector<std::string>{"radius", "axis", "length"};
    for (const char* key : {"normal", "edge", "size", "radius", "axis", "length"})
        if (const auto v = m.find(key); v && std::find(own.begin(), own.end(), key) == own.end())
            v->fail("is not a key of a " + shape + " (" + join_names(own) + ")");
    if (shape == "plane") {
        b.shape = RigidShape::Plane;
        b.point = m.at("point", "a point [x, y, z] of the plane face").vec3();
        b.normal = unit_vector(
            m.at("normal", "the face normal [nx, ny, nz], pointing towards the shell"), "normal");
        if (m.find("edge") || m.find("size")) {  // a rectangle from `point`
            const YamlValue edge = m.at("edge", "the direction [x, y, z] of the face's first side");
            const Vec3 e = edge.vec3() - edge.vec3().dot(b.normal) * b.normal;
            if (!(e.norm() > 1e-9 * edge.vec3().norm()))
                edge.fail("must not be along the normal: it is a direction in the face");
            b.edge = e.normalized();
            const auto size =
                m.at("size", "the sides [l, m] of the face").list_of(2, "two sides", "[l, m]");
            b.size_l = size[0].non_negative();  // 0: unbounded that way
            b.size_m = size[1].non_negative();
            if (!(b.size_l > 0 || b.size_m > 0))
                m.at("size", "").fail("give at least one side > 0 (0: unbounded that way)");
        }
    } else if (shape == "sphere") {
        b.shape = RigidShape::Sphere;
        b.point = m.at("point", "the centre [x, y, z] of the sphere").vec3();
        b.radius = m.at("radius", "the radius, a number > 0").positive();
    } else {
        b.shape = RigidShape::Cylinder;
        b.point =
            m.at("point", "a point [x, y, z] of the axis (an end of a finite cylinder)").vec3();
        b.axis = unit_vector(m.at("axis", "the axis direction [x, y, z]"), "axis");
        b.radius = m.at("radius", "the radius, a number > 0").positive();
        b.length = m.non_negative_or("length", 0.0);
    }
}

}  // namespace

void read_rigid_bodies(const YamlValue& v, Model& model) {
    for (const YamlValue& item : v.list("rigid bodies")) {
        const YamlMap m = item.map({"name", "mass", "shape", "point", "normal", "velocity", "fixed",
                                    "radius", "axis", "length", "edge", "size"});
        RigidBody b;
        const YamlValue name = m.at("name", "a name for the body, used in contact and histories");
        b.name = name.name();
        if (b.name.empty() || b.name.find_first_of(",\"\n\r ") != std::string::npos)
            name.fail("a body name must be a single word without commas or quotes, got " +
                      name.describe());
        for (const RigidBody& other : model.rigid_bodies)
            if (other.name == b.name) name.fail("the rigid body '" + b.name + "' is defined twice");
        const std::string shape = m.choice_or("shape", {"plane", "sphere", "cylinder"}, "plane");
        b.fixed = m.choice_or("fixed", {"true", "false"}, "false") == "true";
        if (b.fixed) {
            if (const auto mass = m.find("mass"))
                mass->fail("a fixed body has infinite mass; remove `mass` or set `fixed: false`");
        } else {
            b.mass =
                m.at("mass", "the mass of the body, a number > 0 (or `fixed: true`)").positive();
        }
        read_shape(m, shape, b);
        if (const auto vel = m.find("velocity")) b.velocity = vel->vec3();
        model.rigid_bodies.push_back(b);
    }
}

namespace {

/// `friction` (a number >= 0 or stick), `friction_dynamic` and `friction_decay` (theory.md
/// §8.4, eq. 8.4-5: LS-DYNA's FS, FD, DC).
void read_friction(const YamlMap& m, ContactDefinition& c) {
    const auto f = m.find("friction");
    if (f) {
        c.friction = f->is_scalar() && f->text() == "stick" ? std::numeric_limits<Real>::infinity()
                                                            : f->non_negative();
    }
    const auto fd = m.find("friction_dynamic");
    const auto dc = m.find("friction_decay");
    if ((fd || dc) && !(c.friction > 0 && std::isfinite(c.friction)))
        (fd ? *fd : *dc)
            .fail(
                "friction_dynamic and friction_decay need a static coefficient: a number "
                "friction > 0");
    if (fd && !dc)
        fd->fail(
            "friction_dynamic needs friction_decay (> 0: how fast the coefficient falls "
            "from friction to friction_dynamic with the sliding speed)");
    if (fd) c.friction_dynamic = fd->non_negative();
    if (dc) {
        c.friction_decay = dc->non_negative();
        if (!fd) c.friction_dynamic = c.friction;
    }
}

}  // namespace

void read_contact(const YamlValue& v, Model& model) {
    for (const YamlValue& item : v.list("contact definitions")) {
        const YamlMap any = item.open_map("contact settings");
        const std::string type = any.at("type", "self or rigid").choice({"self", "rigid"});
        ContactDefinition c;
        if (type == "self") {
            const YamlMap m = item.map({"type", "elements", "nodes", "method", "exclusion_radius",
                                        "penalty_scale", "max_iterations", "friction",
                                        "friction_dynamic", "friction_decay"});
            c.type = ContactType::Self;
            c.elements = model.element_sets.at("all");
            if (const auto e = m.find("elements"); e && e->is_list()) {
                // several sets: their union (the two sides of LS-DYNA's surface-to-surface)
                const auto names = e->list("element set names");
                if (names.empty())
                    e->fail("expected an element set name or a non-empty list of them");
                c.elements.clear();
                for (const YamlValue& name : names) {
                    const auto& set = named_element_set(model, name);
                    c.elements.insert(c.elements.end(), set.begin(), set.end());
                }
                std::sort(c.elements.begin(), c.elements.end());
                c.elements.erase(std::unique(c.elements.begin(), c.elements.end()),
                                 c.elements.end());
            } else if (e) {
                c.elements = named_element_set(model, *e);
            }
            // a node set: those particles alone touch the faces (one-way, LS-DYNA's
            // NODES_TO_SURFACE with a node set)
            if (const auto n = m.find("nodes")) {
                c.nodes = named_node_set(model, *n);
                if (c.nodes.empty()) n->fail("the node set of a self-contact must not be empty");
            }
            c.exclusion_radius = m.non_negative_or("exclusion_radius", 0.0);
            read_contact_method(m, c);
            read_friction(m, c);
        } else {
            const YamlMap m =
                item.map({"type", "body", "nodes", "method", "penalty_scale", "max_iterations",
                          "friction", "friction_dynamic", "friction_decay", "offset",
                          "initially_inside", "except_nodes"});
            c.type = ContactType::Rigid;
            c.body = named_rigid_body(model, m.at("body", "the name of a rigid body"));
            c.nodes = m.find("nodes") ? named_node_set(model, *m.find("nodes"))
                                      : model.node_sets.at("all");
            if (const auto except = m.find("except_nodes")) {
                // LS-DYNA's NSIDEX: the particles the body does not act on
                const auto& left_out = named_node_set(model, *except);
                std::vector<Index> kept;
                std::set_difference(c.nodes.begin(), c.nodes.end(), left_out.begin(),
                                    left_out.end(), std::back_inserter(kept));
                c.nodes = std::move(kept);
            }
            read_contact_method(m, c);
            read_friction(m, c);
            c.offset = m.non_negative_or("offset", -1.0);
            // A particle that starts inside the face (its offset included) would be thrown out
            // of it in one step: an error, or (`initially_inside: release`, as LS-DYNA's walls
            // release the nodes that start behind them) left out of this contact, with a note.
            const bool release =
                m.choice_or("initially_inside", {"error", "release"}, "error") == "release";
            const RigidBody& rb = model.rigid_bodies[static_cast<std::size_t>(c.body)];
            const std::vector<Real> h = node_thickness(model);
            std::vector<Index> kept;
            long released = 0;
            Real deepest = 0;
            for (const Index p : c.nodes) {
                const auto up = static_cast<std::size_t>(p);
                const RigidFacePoint face = rigid_face_point(rb, model.nodes[up], Vec3::Zero());
                const Real offset = c.offset >= 0 ? c.offset : 0.5 * h[up];
                const Real behind =
                    face.faces ? offset - face.normal.dot(model.nodes[up] - face.anchor) : 0.0;
                if (!(behind > 1e-9 * (1.0 + rb.point.norm()))) {
                    kept.push_back(p);
                    continue;
                }
                if (!release)
                    item.fail(
                        "particle " + std::to_string(p + 1) + " starts " + std::to_string(behind) +
                        " inside the face of rigid body '" + rb.name +
                        "' (a particle touches it with a ball of half its thickness, or of the "
                        "contact's offset; the face normal points towards the shell); move the "
                        "body by that much, check the sign of its normal, or leave such "
                        "particles out with initially_inside: release");
                ++released;
                deepest = std::max(deepest, behind);
            }
            if (released > 0) {
                c.nodes = std::move(kept);
                model.notes.push_back(fmt::format(
                    "contact {} with rigid body '{}': {} particle(s) start inside its face (the "
                    "deepest by {:.4g}): left out of this contact (initially_inside: release, as "
                    "LS-DYNA releases the nodes that start behind a wall)",
                    model.contacts.size() + 1, rb.name, released, deepest));
            }
        }
        model.contacts.push_back(c);
    }
}

}  // namespace fpmshell
