// Lap joints of spot-welded steel sheets (tests of theory.md eq. 6.11-13): sheets 2 mm apart,
// the lower one clamped, the top one pulled.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/model/model.hpp"
#include "one_section_model.hpp"

namespace fpmshell::test {

inline constexpr Real k_lap_thickness = 0.002;  // m, each sheet and the gaps

/// `sheets` sheets of 0.2 m width, 5 x 2 squares of 0.1 m each: sheet 0 over x in [0, 0.5] at
/// z = 0, the others over [0.4, 0.9] at z = 0.002 k. Each sheet k > 0 is welded to sheet k - 1
/// at the particles they share in x and y with x <= 0.5 (the overlap: 6 welds). Sheet 0's edge
/// x = 0 is clamped; the top sheet's edge x = 0.9 is pulled along +x by `pull` N in all,
/// ramped from 0 at t = 0 to full at 2 ms.
struct LapJoint {
    Model model;
    std::vector<std::vector<Index>> sheet;        ///< per sheet, its particles
    std::vector<std::vector<std::size_t>> welds;  ///< per sheet k > 0: its welds to sheet k - 1
    Real pull = 0;
};

inline LapJoint lap_joint(int sheets, Real pull, NodalRigidBody::Failure failure) {
    MeshData mesh;
    LapJoint j;
    j.pull = pull;
    for (int k = 0; k < sheets; ++k) {
        PlateParams pp;
        pp.length_x = 0.5;
        pp.length_y = 0.2;
        pp.nx = 5;
        pp.ny = 2;
        pp.pattern = DiagonalPattern::Alternate;
        pp.origin = Vec3(k == 0 ? 0.0 : 0.4, 0.0, k_lap_thickness * k);
        const MeshData one = generate_plate(pp);
        const auto first = static_cast<Index>(mesh.nodes.size());
        j.sheet.emplace_back();
        for (std::size_t p = 0; p < one.nodes.size(); ++p) {
            mesh.nodes.push_back(one.nodes[p]);
            j.sheet.back().push_back(first + static_cast<Index>(p));
        }
        for (const auto& t : one.triangles)
            mesh.triangles.push_back({first + t[0], first + t[1], first + t[2]});
    }
    j.model = test::one_section_model(mesh, k_lap_thickness);
    Model& m = j.model;
    m.control.end_time = 1;
    j.welds.resize(static_cast<std::size_t>(sheets));
    for (std::size_t k = 1; k < j.sheet.size(); ++k)
        for (const Index a : j.sheet[k - 1])
            for (const Index b : j.sheet[k]) {
                const Vec3 d =
                    m.nodes[static_cast<std::size_t>(b)] - m.nodes[static_cast<std::size_t>(a)];
                if (std::hypot(d.x(), d.y()) < 1e-12 &&
                    m.nodes[static_cast<std::size_t>(a)].x() < 0.5 + 1e-12) {
                    NodalRigidBody weld;
                    weld.nodes = {a, b};
                    weld.failure = failure;
                    j.welds[k].push_back(m.nodal_rigid_bodies.size());
                    m.nodal_rigid_bodies.push_back(weld);
                }
            }
    BoundaryCondition clamp;
    clamp.fixed = {true, true, true, true, true, true};
    std::vector<Index> far_edge;
    for (const Index p : j.sheet.front())
        if (m.nodes[static_cast<std::size_t>(p)].x() < 1e-12) clamp.nodes.push_back(p);
    for (const Index p : j.sheet.back())
        if (m.nodes[static_cast<std::size_t>(p)].x() > 0.9 - 1e-12) far_edge.push_back(p);
    m.boundary.push_back(clamp);
    m.curves.push_back({"ramp", {{0, 0}, {2e-3, 1}, {1, 1}}});
    for (const Index p : far_edge)
        m.loads.push_back({LoadType::Force,
                           {p},
                           {},
                           0,
                           Vec3(pull / static_cast<Real>(far_edge.size()), 0, 0),
                           0});
    return j;
}

/// The pull at time t (the ramp of lap_joint).
inline Real pull_at(const LapJoint& j, Real t) { return j.pull * std::min(t / 2e-3, 1.0); }

}  // namespace fpmshell::test
