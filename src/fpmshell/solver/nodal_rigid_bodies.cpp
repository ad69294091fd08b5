// Nodal rigid bodies: the merge of groups that share particles, and the rigid projection of the
// velocities (theory.md §6.11).
#include "fpmshell/solver/nodal_rigid_bodies.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>

#include "fpmshell/solver/particle_state.hpp"

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

/// The groups of particles that move rigidly: the model's constraints, and the particles of each
/// section of a rigid material (one body per section), with the components each holds fixed.
std::vector<std::pair<NodalRigidBody, std::array<bool, 6>>> rigid_groups(const Model& model) {
    std::vector<std::pair<NodalRigidBody, std::array<bool, 6>>> groups;
    for (const NodalRigidBody& g : model.nodal_rigid_bodies) groups.push_back({g, {}});
    // the particles of each section of a rigid material
    for (std::size_t s = 0; s < model.sections.size(); ++s) {
        const Material& material =
            model.materials[static_cast<std::size_t>(model.sections[s].material)];
        if (!material.rigid) continue;
        NodalRigidBody body;
        for (std::size_t e = 0; e < model.triangles.size(); ++e)
            if (static_cast<std::size_t>(model.element_section[e]) == s)
                body.nodes.insert(body.nodes.end(), model.triangles[e].begin(),
                                  model.triangles[e].end());
        std::sort(body.nodes.begin(), body.nodes.end());
        body.nodes.erase(std::unique(body.nodes.begin(), body.nodes.end()), body.nodes.end());
        if (!body.nodes.empty()) groups.push_back({std::move(body), material.rigid_fixed});
    }
    return groups;
}

}  // namespace

NodalRigidBodies::NodalRigidBodies(const Model& model) {
    const auto groups = rigid_groups(model);
    if (groups.empty()) return;
    std::vector<Index> parent(model.nodes.size());
    std::iota(parent.begin(), parent.end(), Index{0});
    std::vector<std::uint8_t> member(model.nodes.size(), 0);
    for (const auto& [group, unused] : groups) {
        (void)unused;
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
            body_of_root[r] = static_cast<Index>(bodies_.size());
            bodies_.emplace_back();
        }
        bodies_[static_cast<std::size_t>(body_of_root[r])].push_back(static_cast<Index>(p));
    }
    // a body holds fixed every component that a group merged into it holds fixed
    fixed_.assign(bodies_.size(), {});
    for (const auto& [group, fixed] : groups) {
        const auto b = static_cast<std::size_t>(
            body_of_root[static_cast<std::size_t>(root_of(parent, group.nodes.front()))]);
        for (std::size_t k = 0; k < 6; ++k) fixed_[b][k] = fixed_[b][k] || fixed[k];
    }
}

std::vector<Real> NodalRigidBodies::contact_masses(const std::vector<Real>& mass) const {
    std::vector<Real> out = mass;
    for (const std::vector<Index>& body : bodies_) {
        Real total = 0;
        for (const Index p : body) total += mass[static_cast<std::size_t>(p)];
        for (const Index p : body) out[static_cast<std::size_t>(p)] = total;
    }
    return out;
}

void NodalRigidBodies::make_rigid(ParticleState& s, Real dt_new) const {
    const auto n_bodies = static_cast<std::ptrdiff_t>(bodies_.size());
#pragma omp parallel for schedule(static) if (n_bodies >= 64)
    for (std::ptrdiff_t b = 0; b < n_bodies; ++b) {
        const std::vector<Index>& body = bodies_[static_cast<std::size_t>(b)];
        // mass, centre of mass at x^n, linear momentum (eq. 6.11-1)
        Real mass = 0;
        Vec3 centre = Vec3::Zero(), momentum = Vec3::Zero();
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            mass += s.mass[p];
            centre += s.mass[p] * s.x[p];
            momentum += s.mass[p] * s.v[p];
        }
        centre /= mass;
        const std::array<bool, 6>& fixed = fixed_[static_cast<std::size_t>(b)];
        Vec3 velocity = momentum / mass;
        for (int k = 0; k < 3; ++k)
            if (fixed[static_cast<std::size_t>(k)]) velocity[k] = 0;  // eq. 6.11-6
        // angular momentum and inertia tensor about the centre (eq. 6.11-2); a shell particle
        // turns in its tangent plane only, so its own inertia has no part about its normal
        Vec3 spin = Vec3::Zero();
        Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            const Vec3 r = s.x[p] - centre;
            spin += s.mass[p] * r.cross(s.v[p] - velocity) + s.inertia[p] * s.omega[p];
            inertia +=
                s.mass[p] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
            const Vec3& n = s.normal[p];
            inertia += s.full_rotation[p]
                           ? Eigen::Matrix3d(s.inertia[p] * Eigen::Matrix3d::Identity())
                           : Eigen::Matrix3d(s.inertia[p] *
                                             (Eigen::Matrix3d::Identity() - n * n.transpose()));
        }
        // omega = I^+ L (eq. 6.11-3): the pseudo-inverse leaves out a rotation no particle's
        // mass or inertia resists (two welded particles on the line of their normals cannot
        // turn each other about it), which carries no angular momentum either. Fixed rotation
        // axes (eq. 6.11-6): the free axes' block of I against their part of L; the fixed rows
        // and columns become the largest inertia times the identity, and their omega is 0.
        if (fixed[3] || fixed[4] || fixed[5]) {
            const Real scale = std::max(inertia.trace(), Real(0));
            for (int k = 0; k < 3; ++k) {
                if (!fixed[static_cast<std::size_t>(3 + k)]) continue;
                inertia.row(k).setZero();
                inertia.col(k).setZero();
                inertia(k, k) = scale;
                spin[k] = 0;
            }
        }
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
        const Vec3 values = eigen.eigenvalues();
        const Real floor = 1e-12 * std::max(values.maxCoeff(), Real(0));
        Vec3 projected = eigen.eigenvectors().transpose() * spin;
        for (int k = 0; k < 3; ++k) projected[k] = values[k] > floor ? projected[k] / values[k] : 0;
        Vec3 omega = eigen.eigenvectors() * projected;
        for (int k = 0; k < 3; ++k)
            if (fixed[static_cast<std::size_t>(3 + k)]) omega[k] = 0;  // exactly
        // each particle moves with the body, the rotation over the step exact (eq. 6.11-4)
        const Real angle = dt_new * omega.norm();
        const Eigen::Matrix3d turn =
            angle > 0 ? Eigen::AngleAxisd(angle, omega.normalized()).toRotationMatrix()
                      : Eigen::Matrix3d::Identity();
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            const Vec3 r = s.x[p] - centre;
            s.v[p] = velocity + (turn * r - r) / dt_new;
            const Vec3& n = s.normal[p];
            s.omega[p] = s.full_rotation[p] ? omega : Vec3(omega - n.dot(omega) * n);
        }
    }
}

}  // namespace fpmshell
