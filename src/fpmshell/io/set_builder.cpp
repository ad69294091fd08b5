// Geometric sets (see set_builder.hpp).
#include "fpmshell/io/set_builder.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

namespace fpmshell {

Real model_size(const std::vector<Vec3>& nodes) {
    if (nodes.empty()) return 0;
    Vec3 lo = nodes.front();
    Vec3 hi = nodes.front();
    for (const Vec3& x : nodes) {
        lo = lo.cwiseMin(x);
        hi = hi.cwiseMax(x);
    }
    return (hi - lo).norm();
}

std::vector<Index> nodes_near(const std::vector<Vec3>& nodes, const Vec3& point,
                              std::optional<Real> tolerance) {
    std::vector<Index> out;
    if (tolerance) {
        const Real tol2 = *tolerance * *tolerance;
        for (std::size_t i = 0; i < nodes.size(); ++i)
            if ((nodes[i] - point).squaredNorm() <= tol2) out.push_back(static_cast<Index>(i));
        return out;
    }
    Real best = std::numeric_limits<Real>::infinity();
    Index best_index = -1;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Real d2 = (nodes[i] - point).squaredNorm();
        if (d2 < best) {
            best = d2;
            best_index = static_cast<Index>(i);
        }
    }
    if (best_index >= 0) out.push_back(best_index);
    return out;
}

std::vector<Index> nodes_on_plane(const std::vector<Vec3>& nodes, const Vec3& point,
                                  const Vec3& normal, Real tolerance) {
    std::vector<Index> out;
    const Vec3 n = normal.normalized();
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (std::abs((nodes[i] - point).dot(n)) <= tolerance) out.push_back(static_cast<Index>(i));
    return out;
}

namespace {
bool inside(const Vec3& x, const Vec3& lo, const Vec3& hi, Real tol) {
    for (int k = 0; k < 3; ++k)
        if (x[k] < lo[k] - tol || x[k] > hi[k] + tol) return false;
    return true;
}
}  // namespace

std::vector<Index> nodes_in_box(const std::vector<Vec3>& nodes, const Vec3& lo, const Vec3& hi,
                                Real tolerance) {
    std::vector<Index> out;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (inside(nodes[i], lo, hi, tolerance)) out.push_back(static_cast<Index>(i));
    return out;
}

std::vector<Index> elements_within(const std::vector<std::array<Index, 3>>& triangles,
                                   const std::vector<Index>& node_set, std::size_t n_nodes) {
    std::vector<char> member(n_nodes, 0);
    for (const Index v : node_set) member[static_cast<std::size_t>(v)] = 1;
    std::vector<Index> out;
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        const auto& t = triangles[e];
        if (member[static_cast<std::size_t>(t[0])] && member[static_cast<std::size_t>(t[1])] &&
            member[static_cast<std::size_t>(t[2])])
            out.push_back(static_cast<Index>(e));
    }
    return out;
}

std::vector<Index> elements_in_box(const std::vector<Vec3>& nodes,
                                   const std::vector<std::array<Index, 3>>& triangles,
                                   const Vec3& lo, const Vec3& hi, Real tolerance) {
    std::vector<Index> out;
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        const auto& t = triangles[e];
        const Vec3 c =
            (nodes[static_cast<std::size_t>(t[0])] + nodes[static_cast<std::size_t>(t[1])] +
             nodes[static_cast<std::size_t>(t[2])]) /
            3.0;
        if (inside(c, lo, hi, tolerance)) out.push_back(static_cast<Index>(e));
    }
    return out;
}

namespace {

/// The nodes of the mesh file's numbers `ids` (MeshData::node_tag), sorted.
std::vector<Index> nodes_numbered(const MeshData& mesh, const YamlValue& ids) {
    if (mesh.node_tag.empty())
        ids.fail(
            "node_ids needs a mesh file with node numbers (.inp or .k); this mesh has none: use "
            "near, plane or box");
    std::vector<Index> nodes;
    for (const YamlValue& id : ids.list("node numbers")) {
        const long long number = id.integer(1, std::numeric_limits<long long>::max());
        const auto it = std::lower_bound(mesh.node_tag.begin(), mesh.node_tag.end(), number);
        if ((it == mesh.node_tag.end() || *it != number) &&
            std::binary_search(mesh.inner_node_tag.begin(), mesh.inner_node_tag.end(), number))
            continue;  // inside a rigid part of solids: its body's outer faces carry it
        if (it == mesh.node_tag.end() || *it != number)
            id.fail("node " + std::to_string(number) +
                    " is not a node of the mesh's shells (the mesh file does not define it, or "
                    "no shell element uses it)");
        nodes.push_back(static_cast<Index>(it - mesh.node_tag.begin()));
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
}

/// The triangles of the mesh file's element numbers `ids` (MeshData::element_tag: both halves of
/// a split quadrangle), sorted.
std::vector<Index> elements_numbered(const MeshData& mesh, const YamlValue& ids) {
    if (mesh.element_tag.empty() || mesh.node_tag.empty())
        ids.fail(
            "element_ids needs a mesh file with element numbers (.inp or .k); this mesh has none: "
            "use near, plane or box");
    std::vector<std::pair<std::int64_t, Index>> by_number;
    by_number.reserve(mesh.element_tag.size());
    for (std::size_t t = 0; t < mesh.element_tag.size(); ++t)
        by_number.emplace_back(mesh.element_tag[t], static_cast<Index>(t));
    std::sort(by_number.begin(), by_number.end());
    std::vector<Index> elements;
    for (const YamlValue& id : ids.list("element numbers")) {
        const long long number = id.integer(1, std::numeric_limits<long long>::max());
        auto it = std::lower_bound(by_number.begin(), by_number.end(),
                                   std::pair<std::int64_t, Index>{number, -1});
        if (it == by_number.end() || it->first != number)
            id.fail("element " + std::to_string(number) + " is not a shell element of the mesh");
        for (; it != by_number.end() && it->first == number; ++it) elements.push_back(it->second);
    }
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    return elements;
}

}  // namespace

void add_user_sets(const YamlValue& sets, MeshData& mesh) {
    const YamlMap map = sets.open_map("set names to set definitions");
    const Real size = model_size(mesh.nodes);
    std::vector<std::string> mesh_names;
    for (const auto& [name, members] : mesh.node_sets) mesh_names.push_back(name);
    for (const auto& [name, members] : mesh.element_sets) mesh_names.push_back(name);

    for (const auto& [name, value] : map.entries()) {
        if (name == "all")
            value.fail(
                "the name 'all' is reserved for the set of every node and element; "
                "choose another name");
        if (std::find(mesh_names.begin(), mesh_names.end(), name) != mesh_names.end())
            value.fail("a set named '" + name +
                       "' is already defined by the mesh; choose another name");
        const YamlMap def =
            value.map({"near", "plane", "box", "node_ids", "element_ids", "tolerance"});
        if (def.count({"near", "plane", "box", "node_ids", "element_ids"}) != 1)
            value.fail(
                "a set needs exactly one of near: [x, y, z], plane: {point, normal}, "
                "box: [[xmin, ymin, zmin], [xmax, ymax, zmax]], node_ids: [n1, n2, ...] or "
                "element_ids: [e1, e2, ...]");
        std::optional<Real> tolerance;
        if (const auto t = def.find("tolerance")) tolerance = t->non_negative();

        std::vector<Index> nodes;
        std::vector<Index> elements;
        std::string how;
        if (const auto ids = def.find("node_ids")) {
            if (tolerance) def.at("tolerance").fail("a set of node_ids takes no tolerance");
            nodes = nodes_numbered(mesh, *ids);
            elements = elements_within(mesh.triangles, nodes, mesh.nodes.size());
            how = "node_ids lists no node";
        } else if (const auto eids = def.find("element_ids")) {
            if (tolerance) def.at("tolerance").fail("a set of element_ids takes no tolerance");
            elements = elements_numbered(mesh, *eids);
            for (const Index e : elements)
                for (const Index n : mesh.triangles[static_cast<std::size_t>(e)])
                    nodes.push_back(n);
            std::sort(nodes.begin(), nodes.end());
            nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
            how = "element_ids lists no element";
        } else if (const auto near = def.find("near")) {
            const Vec3 point = near->vec3();
            nodes = nodes_near(mesh.nodes, point, tolerance);
            elements = elements_within(mesh.triangles, nodes, mesh.nodes.size());
            how =
                "no node lies within the tolerance of the point; increase `tolerance` or "
                "omit it to take the closest node";
        } else if (const auto plane = def.find("plane")) {
            const YamlMap p = plane->map({"point", "normal"});
            const Vec3 point = p.at("point", "a list of 3 numbers").vec3();
            const YamlValue normal_value = p.at("normal", "a list of 3 numbers");
            const Vec3 normal = normal_value.vec3();
            if (!(normal.norm() > 0)) normal_value.fail("the normal must not be the zero vector");
            nodes = nodes_on_plane(mesh.nodes, point, normal, tolerance.value_or(1e-6 * size));
            elements = elements_within(mesh.triangles, nodes, mesh.nodes.size());
            how =
                "no node lies on the plane within the tolerance; check the point and normal or "
                "increase `tolerance`";
        } else {
            const YamlValue box = *def.find("box");
            const auto corners = box.list_of(
                2, "two corners", "two corners [[xmin, ymin, zmin], [xmax, ymax, zmax]]");
            const Vec3 lo = corners[0].vec3();
            const Vec3 hi = corners[1].vec3();
            for (int k = 0; k < 3; ++k)
                if (lo[k] > hi[k])
                    box.fail(
                        "the first corner must be the minimum and the second the maximum in "
                        "each coordinate, but component " +
                        std::to_string(k + 1) + " of the first is larger");
            const Real tol = tolerance.value_or(1e-9 * size);
            nodes = nodes_in_box(mesh.nodes, lo, hi, tol);
            elements = elements_in_box(mesh.nodes, mesh.triangles, lo, hi, tol);
            how = "no node lies inside the box; check its corners";
        }
        if (nodes.empty()) value.fail("the set is empty: " + how);
        mesh.node_sets[name] = std::move(nodes);
        mesh.element_sets[name] = std::move(elements);
    }
}

}  // namespace fpmshell
