// Particle shares of a rigid section with a given inertia (see rigid_inertia_shares.hpp).
#include "fpmshell/model/rigid_inertia_shares.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "fpmshell/core/symmetric_solve.hpp"

namespace fpmshell {

RigidInertiaShares rigid_inertia_shares(const Model& model, Index section) {
    RigidInertiaShares out;
    const RigidInertia& body = model.sections[static_cast<std::size_t>(section)].inertia;
    // the area shares w_i (a third of each face's area to each corner), summed in element order
    std::map<Index, Real> area_share;
    Real area_sum = 0;
    std::size_t n_faces = 0;
    for (std::size_t e = 0; e < model.triangles.size(); ++e) {
        if (model.element_section[e] != section) continue;
        const auto& t = model.triangles[e];
        const Vec3& p0 = model.nodes[static_cast<std::size_t>(t[0])];
        const Real area = 0.5 * (model.nodes[static_cast<std::size_t>(t[1])] - p0)
                                    .cross(model.nodes[static_cast<std::size_t>(t[2])] - p0)
                                    .norm();
        for (const Index p : t) area_share[p] += area / 3.0;
        area_sum += area;
        ++n_faces;
    }
    if (area_share.empty() || !(area_sum > 0)) {
        out.problem = "its faces have no area";
        return out;
    }
    Vec3 mean = Vec3::Zero();
    for (const auto& [p, a] : area_share)
        mean += (a / area_sum) * model.nodes[static_cast<std::size_t>(p)];
    Mat3 spread = Mat3::Zero();
    for (const auto& [p, a] : area_share) {
        const Vec3 r = model.nodes[static_cast<std::size_t>(p)] - mean;
        spread += (a / area_sum) * r * r.transpose();
    }
    // a = S^+ (c - xbar): the pseudo-inverse, as the particles of a flat part span a plane only
    const Vec3 tilt = symmetric_pseudo_solve(spread, body.centre - mean);
    // the rotary inertia: the mass share times the faces' mean area / 8 (§6.2 option B, h = 0)
    const Real gyration2 = area_sum / static_cast<Real>(n_faces) / 8.0;
    Vec3 first = Vec3::Zero();
    for (const auto& [p, a] : area_share) {
        const Vec3& x = model.nodes[static_cast<std::size_t>(p)];
        const Real m = body.mass * (a / area_sum) * (1.0 + tilt.dot(x - mean));
        out.particles.push_back(p);
        out.mass.push_back(m);
        out.inertia.push_back(m * gyration2);
        first += m * x;
        if (!(m > 0) && !out.problem)
            out.problem =
                "its centre of mass lies so far from the middle of its faces that "
                "particle " +
                std::to_string(p + 1) + " would get a negative share of its mass";
    }
    const Real size = std::sqrt(std::max(spread.trace(), Real(0)));
    if (!out.problem && (first / body.mass - body.centre).norm() > 1e-9 * std::max(size, 1e-300))
        out.problem = "its centre of mass lies off the plane of its particles";
    return out;
}

}  // namespace fpmshell
