// The rigid bodies of a model: groups merged by union-find, and the `boundary` entries of type
// rigid_body applied to them (theory.md §6.11, eqs. 6.11-6, 6.11-7).
#include "fpmshell/model/rigid_body_partition.hpp"

#include <algorithm>
#include <numeric>

namespace fpmshell {

namespace {

/// Union-find over the particles, with path halving.
Index root_of(std::vector<Index>& parent, Index p) {
    while (parent[static_cast<std::size_t>(p)] != p) {
        auto& up = parent[static_cast<std::size_t>(p)];
        up = parent[static_cast<std::size_t>(up)];
        p = up;
    }
    return p;
}

/// The `boundary` entries of type rigid_body on the bodies: their held and prescribed
/// components; the first entry that cannot be applied is noted in `problem`.
void apply_rigid_body_entries(const Model& model, RigidBodyPartition& out) {
    for (std::size_t i = 0; i < model.boundary.size(); ++i) {
        const BoundaryCondition& bc = model.boundary[i];
        if (bc.rigid_elements.empty()) continue;
        auto body_of = [&](Index e) {
            return out.body_of_particle[static_cast<std::size_t>(
                model.triangles[static_cast<std::size_t>(e)][0])];
        };
        const Index body = body_of(bc.rigid_elements.front());
        for (const Index e : bc.rigid_elements)
            if (body < 0 || body_of(e) != body) {
                out.problem = {i,
                               "the elements of rigid_body are not one rigid body (give the "
                               "elements of one rigid part, or join the parts)"};
                return;
            }
        const auto b = static_cast<std::size_t>(body);
        const std::string conflict =
            "a component of this rigid body's motion is already held or prescribed by another "
            "entry or the body's material";
        for (std::size_t k = 0; k < 6; ++k) {
            if (bc.fixed[k] && out.prescribed[b][k].kind != PrescribedKind::None) {
                out.problem = {i, conflict};
                return;
            }
            out.held[b][k] = out.held[b][k] || bc.fixed[k];
        }
        if (bc.prescribed == PrescribedKind::None) continue;
        const std::size_t first = bc.prescribed == PrescribedKind::AngularVelocity ? 3 : 0;
        for (std::size_t k = 0; k < 3; ++k) {
            if (!bc.components[k]) continue;
            if (out.held[b][first + k]) {
                out.problem = {i, conflict};
                return;
            }
            out.prescribed[b][first + k] = {bc.prescribed, bc.value[static_cast<Eigen::Index>(k)],
                                            bc.curve};
            out.held[b][first + k] = true;
        }
    }
}

}  // namespace

std::vector<RigidGroup> rigid_groups(const Model& model, const std::vector<std::uint8_t>& let_go) {
    std::vector<RigidGroup> groups;
    for (std::size_t g = 0; g < model.nodal_rigid_bodies.size(); ++g)
        if (let_go.empty() || !let_go[g])
            groups.push_back({model.nodal_rigid_bodies[g].nodes, {}, static_cast<long>(g)});
    // the particles of each section of a rigid material
    for (std::size_t s = 0; s < model.sections.size(); ++s) {
        const Material& material =
            model.materials[static_cast<std::size_t>(model.sections[s].material)];
        if (!material.rigid) continue;
        RigidGroup body;
        for (std::size_t e = 0; e < model.triangles.size(); ++e)
            if (static_cast<std::size_t>(model.element_section[e]) == s)
                body.nodes.insert(body.nodes.end(), model.triangles[e].begin(),
                                  model.triangles[e].end());
        std::sort(body.nodes.begin(), body.nodes.end());
        body.nodes.erase(std::unique(body.nodes.begin(), body.nodes.end()), body.nodes.end());
        body.fixed = material.rigid_fixed;
        if (!body.nodes.empty()) groups.push_back(std::move(body));
    }
    return groups;
}

RigidBodyPartition rigid_body_partition(const Model& model,
                                        const std::vector<std::uint8_t>& let_go) {
    RigidBodyPartition out;
    out.body_of_particle.assign(model.nodes.size(), -1);
    const std::vector<RigidGroup> groups = rigid_groups(model, let_go);
    if (!groups.empty()) {
        std::vector<Index> parent(model.nodes.size());
        std::iota(parent.begin(), parent.end(), Index{0});
        std::vector<std::uint8_t> member(model.nodes.size(), 0);
        for (const RigidGroup& group : groups) {
            for (const Index p : group.nodes) {
                member[static_cast<std::size_t>(p)] = 1;
                const Index a = root_of(parent, group.nodes.front()), b = root_of(parent, p);
                if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
            }
        }
        // bodies in the order of their smallest particle, particles ascending
        std::vector<Index> body_of_root(model.nodes.size(), -1);
        for (std::size_t p = 0; p < model.nodes.size(); ++p) {
            if (!member[p]) continue;
            const auto r = static_cast<std::size_t>(root_of(parent, static_cast<Index>(p)));
            if (body_of_root[r] < 0) {
                body_of_root[r] = static_cast<Index>(out.bodies.size());
                out.bodies.emplace_back();
            }
            out.body_of_particle[p] = body_of_root[r];
            out.bodies[static_cast<std::size_t>(body_of_root[r])].push_back(static_cast<Index>(p));
        }
        // a body holds fixed every component that a group merged into it holds fixed
        out.held.assign(out.bodies.size(), {});
        for (const RigidGroup& group : groups) {
            const auto b = static_cast<std::size_t>(
                out.body_of_particle[static_cast<std::size_t>(group.nodes.front())]);
            for (std::size_t k = 0; k < 6; ++k) out.held[b][k] = out.held[b][k] || group.fixed[k];
        }
    }
    out.prescribed.assign(out.bodies.size(), {});
    apply_rigid_body_entries(model, out);
    return out;
}

}  // namespace fpmshell
