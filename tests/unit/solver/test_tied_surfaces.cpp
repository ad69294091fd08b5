// Tied surfaces (solver/tied_surfaces.hpp, theory.md §6.12): a T-joint, a web whose lower edge
// is tied to the faces of a flange it shares no particle with,
// - pulled up and sideways while the flange is clamped at its ends: the tied edge moves with the
//   point of its face, to rounding, and the balance closes (the ties do no work);
// - free, the web thrown sideways: the momentum of the whole is conserved and the flange is
//   dragged along;
// - a particle with no face within the tolerance stays free (counted);
// - a tiebreak lets go at its force, or at its stress times the slave's area;
// - a tie whose face erodes lets go.
#include <gtest/gtest.h>

#include <cmath>

#include "fpmshell/contact/closest_point.hpp"
#include "fpmshell/failure/thresholds/thresholds_failure.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "fpmshell/solver/tied_surfaces.hpp"
#include "one_section_model.hpp"

using namespace fpmshell;

namespace {

constexpr Real k_h = 0.01;

/// Flange: 1 x 0.4 in z = 0, 8 x 4 squares; web: x in [0.3, 0.7], z in [0, 0.3] at y = 0.25,
/// 4 x 3 squares, its 5 lower particles tied to the flange's faces. Returns the model and the
/// web's lower and upper particles.
struct TJoint {
    Model model;
    std::vector<Index> edge, top;
};

TJoint t_joint(bool clamped) {
    PlateParams pp;
    pp.length_x = 1;
    pp.length_y = 0.4;
    pp.nx = 8;
    pp.ny = 4;
    pp.pattern = DiagonalPattern::Alternate;
    MeshData mesh = generate_plate(pp);
    const auto n_flange = static_cast<Index>(mesh.nodes.size());
    const auto e_flange = static_cast<Index>(mesh.triangles.size());
    TJoint t;
    for (int j = 0; j <= 3; ++j)
        for (int i = 0; i <= 4; ++i) {
            const auto p = static_cast<Index>(mesh.nodes.size());
            mesh.nodes.push_back(Vec3(0.3 + 0.1 * i, 0.25, 0.1 * j));
            if (j == 0) t.edge.push_back(p);
            if (j == 3) t.top.push_back(p);
        }
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i) {
            const Index a = n_flange + 5 * j + i, b = a + 1, c = a + 5, d = a + 6;
            mesh.triangles.push_back({a, b, d});
            mesh.triangles.push_back({a, d, c});
        }
    t.model = test::one_section_model(mesh, k_h);
    Model& m = t.model;
    m.control.end_time = 1;
    TiedSurface tie;
    tie.nodes = t.edge;
    for (Index e = 0; e < e_flange; ++e) tie.elements.push_back(e);
    m.tied_surfaces.push_back(tie);
    if (clamped) {
        BoundaryCondition clamp;
        for (Index p = 0; p < n_flange; ++p) {
            const Real x = m.nodes[static_cast<std::size_t>(p)].x();
            if (x < 1e-9 || x > 1 - 1e-9) clamp.nodes.push_back(p);
        }
        clamp.fixed.fill(true);
        m.boundary.push_back(clamp);
    }
    return t;
}

/// The point of the flange each edge particle is tied to, from the initial geometry.
std::vector<std::pair<std::array<Index, 3>, std::array<Real, 3>>> tied_points(const TJoint& t,
                                                                              Index e_flange) {
    std::vector<std::pair<std::array<Index, 3>, std::array<Real, 3>>> out;
    for (const Index s : t.edge) {
        const Vec3& x = t.model.nodes[static_cast<std::size_t>(s)];
        Real best = 1e30;
        std::pair<std::array<Index, 3>, std::array<Real, 3>> pick;
        for (Index e = 0; e < e_flange; ++e) {
            const auto& tri = t.model.triangles[static_cast<std::size_t>(e)];
            const TriangleClosestPoint cp =
                closest_point_on_triangle(x, t.model.nodes[static_cast<std::size_t>(tri[0])],
                                          t.model.nodes[static_cast<std::size_t>(tri[1])],
                                          t.model.nodes[static_cast<std::size_t>(tri[2])], 0.0);
            const Real d = (x - cp.point).norm();
            if (d < best) {
                best = d;
                pick = {tri, cp.xi};
            }
        }
        out.push_back(pick);
    }
    return out;
}

}  // namespace

TEST(TiedSurfaces, TheTiedEdgeMovesWithItsFace) {
    TJoint t = t_joint(true);
    for (const Index p : t.top)
        t.model.loads.push_back({LoadType::Force, {p}, {}, 0, Vec3(0, 300, 1000), -1});
    const auto e_flange = static_cast<Index>(t.model.tied_surfaces[0].elements.size());
    const auto points = tied_points(t, e_flange);
    ExplicitSolver s(t.model);
    ASSERT_NE(s.tied_surfaces(), nullptr);
    EXPECT_EQ(s.tied_surfaces()->tied(), 5u);
    EXPECT_EQ(s.tied_surfaces()->untied(), 0u);
    Real moved = 0;
    for (int step = 0; step < 400; ++step) {
        s.step(1e30);
        for (std::size_t i = 0; i < t.edge.size(); ++i) {
            const auto& [tri, xi] = points[i];
            Vec3 point = Vec3::Zero(), point0 = Vec3::Zero();
            for (std::size_t k = 0; k < 3; ++k) {
                point += xi[k] * s.state().x[static_cast<std::size_t>(tri[k])];
                point0 += xi[k] * t.model.nodes[static_cast<std::size_t>(tri[k])];
            }
            const auto us = static_cast<std::size_t>(t.edge[i]);
            const Vec3 offset0 = t.model.nodes[us] - point0;  // 0 here: the edge lies in the face
            // positions of order 1 m moved by velocities tied to 1e-13 of the largest: rounding
            EXPECT_LT((s.state().x[us] - point - offset0).norm(), 1e-9) << "step " << step;
            moved = std::max(moved, (s.state().x[us] - t.model.nodes[us]).norm());
        }
    }
    EXPECT_GT(moved, 1e-5);                         // the flange bent under the pull
    EXPECT_LT(std::abs(s.energy().error()), 1e-6);  // the ties do no work
}

TEST(TiedSurfaces, AFreeTJointKeepsItsMomentum) {
    TJoint t = t_joint(false);
    std::vector<Index> web;
    for (Index p = static_cast<Index>(t.model.nodes.size()) - 20; p < t.model.n_particles(); ++p)
        web.push_back(p);
    t.model.initial_conditions.push_back({web, Vec3(0, 2, 0), Vec3::Zero()});
    ExplicitSolver s(t.model);
    auto momentum = [&] {
        Vec3 p = Vec3::Zero();
        for (std::size_t i = 0; i < t.model.nodes.size(); ++i)
            p += s.state().mass[i] * s.state().v[i];
        return p;
    };
    // the web's initial momentum; the first step ties it to the flange
    Real web_mass = 0;
    for (const Index p : web) web_mass += s.state().mass[static_cast<std::size_t>(p)];
    const Vec3 p0(0, 2 * web_mass, 0);
    for (int step = 0; step < 300; ++step) s.step(1e30);
    // velocities of ~1 m/s over ~300 steps: rounding of the impulses
    EXPECT_LT((momentum() - p0).norm(), 1e-10 * p0.norm());
    EXPECT_GT(s.state().v[0].y(), 0.0);  // a corner of the flange is dragged along
}

TEST(TiedSurfaces, AParticleWithNoFaceWithinTheToleranceStaysFree) {
    TJoint t = t_joint(false);
    t.model.tied_surfaces[0].nodes.push_back(t.top.front());  // 0.3 m above the flange
    t.model.tied_surfaces[0].tolerance = 0.05;
    const TiedSurfaces ties(t.model, std::vector<Real>(t.model.triangles.size(), k_h));
    EXPECT_EQ(ties.tied(), 5u);
    EXPECT_EQ(ties.untied(), 1u);
}

// A tiebreak (eq. 6.12-2, LS-DYNA's *CONTACT_TIEBREAK_NODES_TO_SURFACE): the web pulled off the
// clamped flange by a force that grows with time, its ties letting go at a normal force F_f.
// Every tie holds while its tension is below F_f; the first to reach it lets go in that step and
// stays loose; once all have, the web leaves the flange. With F_f out of reach none lets go.
TEST(TiedSurfaces, ATiebreakLetsGoAtItsForce) {
    const Real f_f = 40.0;  // N per tie; the pull reaches 5 x 200 N at 1 ms
    for (const bool reachable : {true, false}) {
        TJoint t = t_joint(true);
        t.model.curves.push_back({"ramp", {{0, 0}, {1e-3, 1}}});
        for (const Index p : t.top)
            t.model.loads.push_back({LoadType::Force, {p}, {}, 0, Vec3(0, 0, 200), 0});
        t.model.tied_surfaces[0].normal_force = reachable ? f_f : 1e9;
        ExplicitSolver s(t.model);
        const TiedSurfaces& ties = *s.tied_surfaces();
        std::vector<std::uint8_t> gone(ties.tied(), 0);
        Real highest = 0;
        while (s.time() < 3e-3) {  // the pull held at 1 000 N from 1 ms on
            const std::vector<std::uint8_t> before = gone;
            s.step(1e30);
            for (std::size_t i = 0; i < ties.tied(); ++i) {
                if (before[i]) {
                    EXPECT_EQ(ties.tension()[i], 0.0) << "a loose tie carries nothing";
                    continue;
                }
                highest = std::max(highest, ties.tension()[i]);
                // a tie that held had a tension below F_f; one that let go reached it
                if (ties.tension()[i] >= f_f && reachable) gone[i] = 1;
            }
            std::size_t count = 0;
            for (const std::uint8_t g : gone) count += g;
            EXPECT_EQ(ties.broken(), reachable ? count : 0u) << "t " << s.time();
        }
        if (reachable) {
            EXPECT_EQ(ties.broken(), ties.tied());  // all let go
            // the web's edge has left the flange (it was tied at z = 0): pulled at ~100 m/s^2
            // for over a millisecond
            EXPECT_GT(s.state().x[static_cast<std::size_t>(t.edge[2])].z(), 1e-4);
        } else {
            EXPECT_EQ(ties.broken(), 0u);
            EXPECT_GT(highest, f_f);  // the forces went past F_f: the tie held by choice
        }
    }
}

// A tiebreak given by stresses (eq. 6.12-3, LS-DYNA's *CONTACT_TIEBREAK_SURFACE_TO_SURFACE NFLS):
// each tie's limit is the stress times its slave's area, a third of the web's triangles at it
// (the inner edge particles 0.005 m^2, the end ones 0.0033 and 0.0017): the same pull, every tie
// letting go exactly when its own tension reaches its own limit.
TEST(TiedSurfaces, ATiebreakByStressLetsGoAtItsStressTimesTheArea) {
    const Real sigma_f = 8000;  // Pa: 40 N on an inner particle
    TJoint t = t_joint(true);
    t.model.curves.push_back({"ramp", {{0, 0}, {1e-3, 1}}});
    for (const Index p : t.top)
        t.model.loads.push_back({LoadType::Force, {p}, {}, 0, Vec3(0, 0, 200), 0});
    t.model.tied_surfaces[0].normal_stress = sigma_f;
    std::vector<Real> area(t.model.nodes.size(), 0.0);
    for (const auto& tri : t.model.triangles) {
        const Vec3& a = t.model.nodes[static_cast<std::size_t>(tri[0])];
        const Real third = (t.model.nodes[static_cast<std::size_t>(tri[1])] - a)
                               .cross(t.model.nodes[static_cast<std::size_t>(tri[2])] - a)
                               .norm() /
                           6;
        for (const Index p : tri) area[static_cast<std::size_t>(p)] += third;
    }
    ExplicitSolver s(t.model);
    const TiedSurfaces& ties = *s.tied_surfaces();
    const std::vector<Index> slaves = ties.slaves();
    EXPECT_NEAR(area[static_cast<std::size_t>(t.edge[2])], 0.005, 1e-15);
    std::vector<std::uint8_t> gone(ties.tied(), 0);
    while (s.time() < 3e-3) {
        const std::vector<std::uint8_t> before = gone;
        s.step(1e30);
        for (std::size_t i = 0; i < ties.tied(); ++i) {
            if (before[i]) continue;
            if (ties.tension()[i] >= sigma_f * area[static_cast<std::size_t>(slaves[i])])
                gone[i] = 1;
        }
        std::size_t count = 0;
        for (const std::uint8_t g : gone) count += g;
        EXPECT_EQ(ties.broken(), count) << "t " << s.time();
    }
    EXPECT_EQ(ties.broken(), ties.tied());
}

// §7.6: a tie whose face erodes lets go for good (LS-DYNA releases a tied node whose master
// segment is deleted). The flange, of a plastic steel that fails at 0.5 ms (a failure time,
// *MAT_ADD_EROSION's FAILTM), erodes whole in one step: until then every tie holds, from then
// on every one has let go and carries nothing, and the pulled web leaves the flange.
TEST(TiedSurfaces, TiesToErodedFacesLetGo) {
    TJoint t = t_joint(true);
    Model& m = t.model;
    Material flange = m.materials[0];
    make_bilinear(flange, 2.5e8, 1.0e9);
    ThresholdsFailureParameters at_a_time;
    at_a_time.time = 5e-4;
    flange.failure.criteria.push_back({"thresholds", at_a_time});
    m.materials.push_back(flange);
    m.sections.push_back(m.sections[0]);
    m.sections[1].material = 1;
    const Index e_flange = 64;  // the flange's 8 x 4 squares
    for (Index e = 0; e < e_flange; ++e) m.element_section[static_cast<std::size_t>(e)] = 1;
    m.curves.push_back({"ramp", {{0, 0}, {1e-3, 1}}});
    for (const Index p : t.top)
        m.loads.push_back({LoadType::Force, {p}, {}, 0, Vec3(0, 0, 200), 0});
    ExplicitSolver s(m);
    const TiedSurfaces& ties = *s.tied_surfaces();
    ASSERT_EQ(ties.tied(), t.edge.size());
    while (s.time() < 1.5e-3 && s.steps() < 100000) {
        s.step(1e30);
        if (s.eroded_elements() == 0) {
            EXPECT_EQ(ties.broken(), 0u) << "t " << s.time();
            continue;
        }
        EXPECT_EQ(s.eroded_elements(), static_cast<std::size_t>(e_flange));
        EXPECT_EQ(ties.broken(), ties.tied()) << "t " << s.time();
        for (std::size_t i = 0; i < ties.tied(); ++i) EXPECT_EQ(ties.tension()[i], 0.0);
    }
    EXPECT_GT(s.eroded_elements(), 0u);
    // the web's edge, tied at z = 0, has left the flange's plane: pulled at ~100 m/s^2 for
    // about a millisecond
    EXPECT_GT(s.state().x[static_cast<std::size_t>(t.edge[2])].z(), 1e-5);
}
