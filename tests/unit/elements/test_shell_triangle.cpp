// The whole element (theory.md §3-§5):
// - a rigid motion of any size gives zero force and moment;
// - the nodal forces and moments of any deformation are self-equilibrated in the current
//   configuration (sum of forces and sum of moments about the origin vanish);
// - uniform bending gives the plate moments M = D kappa and membrane strain gives N = h C eps
//   (2-point Gauss integrates the elastic section exactly, theory.md §3.2);
// - objectivity: the same deformation under a 2.3 rad rigid rotation gives the rotated forces.
#include <gtest/gtest.h>

#include <vector>

#include "fpmshell/core/rotation.hpp"
#include "fpmshell/elements/shell_triangle.hpp"
#include "fpmshell/materials/elastic/linear_elastic.hpp"
#include "fpmshell/materials/j2/j2_plastic.hpp"

using namespace fpmshell;

namespace {

ShellRule rule(BendingKernel kernel, int thickness_points = 2, int inplane = 3) {
    ShellRule r;
    r.thickness = 0.05;
    r.inplane = triangle_rule(inplane);
    r.through = thickness_rule(thickness_points);
    r.bending = kernel;
    return r;
}

struct ElementRun {
    ShellTriangleLoads loads;
    std::vector<MaterialPoint> points;
};

ElementRun run(const std::array<Vec3, 3>& base, const std::array<Vec3, 3>& cur,
               const std::array<Vec3, 3>& dth, BendingKernel kernel, int tp = 2, int ip = 3,
               const std::array<Vec3, 3>& drill = k_no_drill_axes) {
    const ShellRule r = rule(kernel, tp, ip);
    const LinearElastic mat(200e9, 0.3);
    ElementRun out;
    out.points.assign(static_cast<std::size_t>(r.n_points()), MaterialPoint{});
    out.loads =
        shell_triangle_loads(reverse_motion(base, cur, dth, drill), r, mat, out.points, 0.0);
    return out;
}

const std::array<Vec3, 3> k_base{Vec3(0.1, 0.0, 0.2), Vec3(1.2, 0.3, 0.1), Vec3(0.2, 0.9, 0.4)};

}  // namespace

TEST(ShellTriangle, RigidMotionGivesZeroLoads) {
    for (BendingKernel kernel : {BendingKernel::Bciz, BendingKernel::Dkt}) {
        const Vec3 phi(1.1, -2.0, 0.4);  // 2.3 rad
        const Mat3 r = rotation_matrix(phi);
        std::array<Vec3, 3> cur, dth;
        for (int i = 0; i < 3; ++i) {
            cur[i] = r * k_base[i] + Vec3(5, 6, -7);
            dth[i] = phi;
        }
        const ElementRun res = run(k_base, cur, dth, kernel);
        for (int i = 0; i < 3; ++i) {
            // E h = 1e10: forces of 1e-3 mean strains of 1e-13, i.e. round-off.
            EXPECT_LT(res.loads.force[i].norm(), 1e-3);
            EXPECT_LT(res.loads.moment[i].norm(), 1e-3);
        }
    }
}

TEST(ShellTriangle, LoadsAreSelfEquilibrated) {
    for (BendingKernel kernel : {BendingKernel::Bciz, BendingKernel::Dkt}) {
        std::array<Vec3, 3> cur{k_base[0] + Vec3(1e-4, -2e-4, 3e-4),
                                k_base[1] + Vec3(-2e-4, 1e-4, 5e-4),
                                k_base[2] + Vec3(3e-4, 2e-4, -1e-4)};
        const std::array<Vec3, 3> dth{Vec3(2e-4, -1e-4, 3e-4), Vec3(-1e-4, 4e-4, 0),
                                      Vec3(3e-4, 1e-4, -2e-4)};
        const ElementRun res = run(k_base, cur, dth, kernel);
        Vec3 f_sum = Vec3::Zero(), m_sum = Vec3::Zero();
        Real scale = 0;
        for (int i = 0; i < 3; ++i) {
            f_sum += res.loads.force[i];
            m_sum += cur[i].cross(res.loads.force[i]) + res.loads.moment[i];
            scale = std::max({scale, res.loads.force[i].norm(), res.loads.moment[i].norm()});
        }
        EXPECT_LT(f_sum.norm(), 1e-12 * scale);
        // Moment balance holds on the base geometry (§4.6); the current geometry differs by
        // O(strain) = 1e-3, so the imbalance is O(strain) of the force scale.
        EXPECT_LT(m_sum.norm(), 2e-3 * scale);
    }
}

TEST(ShellTriangle, LoadsWithDrillAxesAreSelfEquilibratedAndTangent) {
    // Curved-shell nodes (theory.md eq. 4.6b, 4.6c): each node takes the element moment less
    // its part about the node's drill axis (tilted 15-25 deg from the element normal here), and
    // an in-plane couple on side 1-2 balances the drilling part that this leaves. Without the
    // couple the moment balance about the normal misses by ~ |m| sin(tilt), ~0.3 of the scale.
    const Vec3 na = (k_base[1] - k_base[0]).cross(k_base[2] - k_base[0]).normalized();
    const Vec3 ex = (k_base[1] - k_base[0]).normalized(), ey = na.cross(ex);
    const std::array<Vec3, 3> drill{(na + 0.3 * ex).normalized(), (na - 0.4 * ey).normalized(),
                                    (na + 0.3 * ex + 0.3 * ey).normalized()};
    for (BendingKernel kernel : {BendingKernel::Bciz, BendingKernel::Dkt}) {
        // bending alone (the nodes do not move), so that the moments set the scale
        const std::array<Vec3, 3> cur = k_base;
        std::array<Vec3, 3> dth{Vec3(2e-4, -1e-4, 3e-4), Vec3(-1e-4, 4e-4, 0),
                                Vec3(3e-4, 1e-4, -2e-4)};
        for (std::size_t i = 0; i < 3; ++i) dth[i] -= dth[i].dot(drill[i]) * drill[i];
        const ElementRun res = run(k_base, cur, dth, kernel, 2, 3, drill);
        Vec3 f_sum = Vec3::Zero(), m_sum = Vec3::Zero();
        Real scale = 0, along = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            f_sum += res.loads.force[i];
            m_sum += cur[i].cross(res.loads.force[i]) + res.loads.moment[i];
            scale = std::max({scale, res.loads.force[i].norm(), res.loads.moment[i].norm()});
            along = std::max(along, std::abs(res.loads.moment[i].dot(drill[i])));
        }
        EXPECT_LT(f_sum.norm(), 1e-12 * scale);
        // the balance holds on the base geometry, which is the current one here (round-off)
        EXPECT_LT(m_sum.norm(), 1e-12 * scale);
        // each node's moment lies in its tangent plane (no rigid rotation here: round-off)
        EXPECT_LT(along, 1e-12 * scale);
    }
}

TEST(ShellTriangle, SectionResultantsMatchPlateTheory) {
    // Flat element in the xy plane; rotations of a uniform curvature field kxx = k (w = -k x^2/2
    // minus its linear interpolant): theta_x = w,y = 0, theta_y = -w,x.
    const std::array<Vec3, 3> base{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 0.8, 0)};
    const Real k = 1e-4;
    // interpolant of -k x^2/2 through x = 0, 1, 0.3 : l(x, y) = -k/2 x + c y
    const Real c = (-k / 2 * 0.09 + k / 2 * 0.3) / 0.8;
    std::array<Vec3, 3> dth;
    for (int i = 0; i < 3; ++i) {
        const Real x = base[i].x();
        const Real wx = -k * x + k / 2, wy = -c;
        dth[i] = Vec3(wy, -wx, 0);
    }
    for (int tp : {2, 3, 5}) {
        for (BendingKernel kernel : {BendingKernel::Bciz, BendingKernel::Dkt}) {
            const ElementRun res = run(base, base, dth, kernel, tp);
            const Real h = 0.05, e = 200e9, nu = 0.3, d = e * h * h * h / (12 * (1 - nu * nu));
            EXPECT_NEAR(res.loads.bending_moment(0), d * k, 1e-9 * d * k);
            EXPECT_NEAR(res.loads.bending_moment(1), nu * d * k, 1e-9 * d * k);
            EXPECT_NEAR(res.loads.membrane_force.norm(), 0.0, 1e-9 * d * k);
            // Strain work over the step = 1/2 M k A (loading from zero, linear material).
            EXPECT_NEAR(res.loads.strain_work, 0.5 * d * k * k * 0.4, 1e-9 * d * k * k);
        }
    }
}

TEST(ShellTriangle, ObjectiveUnderLargeRigidRotation) {
    const std::array<Vec3, 3> def{k_base[0] + Vec3(1e-4, 0, 2e-4), k_base[1] + Vec3(-1e-4, 2e-4, 0),
                                  k_base[2] + Vec3(0, 1e-4, -3e-4)};
    const std::array<Vec3, 3> bend{Vec3(1e-4, -2e-4, 1e-4), Vec3(-2e-4, 1e-4, 0),
                                   Vec3(3e-4, 0, -1e-4)};
    const ElementRun ref = run(k_base, def, bend, BendingKernel::Bciz);
    const Mat3 r = rotation_matrix(Vec3(0.7, -1.9, 1.2));
    std::array<Vec3, 3> cur, dth;
    for (int i = 0; i < 3; ++i) {
        cur[i] = r * def[i] - Vec3(1, 2, 3);
        dth[i] = rotation_vector(r * rotation_matrix(bend[i]));
    }
    const ElementRun rot = run(k_base, cur, dth, BendingKernel::Bciz);
    for (int i = 0; i < 3; ++i) {
        // Rotated forces equal to round-off relative to their size.
        EXPECT_LT((rot.loads.force[i] - r * ref.loads.force[i]).norm(),
                  1e-9 * ref.loads.force[i].norm() + 1e-6);
        EXPECT_LT((rot.loads.moment[i] - r * ref.loads.moment[i]).norm(),
                  1e-9 * ref.loads.moment[i].norm() + 1e-6);
    }
}

// The plastic element: with a yield stress out of reach it is the elastic element (same
// points, same loads to round-off); past yield, in uniform bending at 5 Lobatto points, the
// moment is that of the section with its outer points at the yield stress and the plastic work
// is positive, while a rigid motion still gives nothing.
TEST(ShellTriangle, PlasticElementReducesToElasticBelowYieldAndYieldsInBending) {
    const std::array<Vec3, 3> cur{Vec3(0.1, 0.0, 0.2), Vec3(1.2003, 0.3, 0.1012),
                                  Vec3(0.2, 0.9002, 0.401)};
    const std::array<Vec3, 3> dth{Vec3(0.001, -0.002, 0.0), Vec3(-0.0015, 0.001, 0.0),
                                  Vec3(0.0005, 0.002, 0.0)};
    const ShellRule r = rule(BendingKernel::Dkt, 5, 7);
    const ReversedTriangle rt = reverse_motion(k_base, cur, dth, k_no_drill_axes);
    const LinearElastic elastic(200e9, 0.3);
    FlowStress flow;
    flow.yield_stress = 1e30;
    const J2Plastic unreachable(200e9, 0.3, flow, RateFactor{}, 1.0);
    std::vector<MaterialPoint> pe(static_cast<std::size_t>(r.n_points())), pp(pe.size());
    const ShellTriangleLoads le = shell_triangle_loads(rt, r, elastic, pe, 0.0);
    const ShellTriangleLoads lp = shell_triangle_loads(rt, r, unreachable, pp, 0.0);
    for (int i = 0; i < 3; ++i) {
        EXPECT_LT((le.force[i] - lp.force[i]).norm(), 1e-12 * le.force[i].norm() + 1e-9);
        EXPECT_LT((le.moment[i] - lp.moment[i]).norm(), 1e-12 * le.moment[i].norm() + 1e-9);
    }
    EXPECT_EQ(lp.plastic_work, 0.0);

    // Yield at a tenth of the elastic surface stress of this increment: the outer points yield.
    const Real surface_stress = pe.back().stress.norm();
    flow.yield_stress = 0.1 * surface_stress;
    const J2Plastic low(200e9, 0.3, flow, RateFactor{}, 1.0);
    std::vector<MaterialPoint> pl(pe.size());
    const ShellTriangleLoads ll = shell_triangle_loads(rt, r, low, pl, 0.0);
    EXPECT_GT(ll.plastic_work, 0.0);
    EXPECT_LE(ll.plastic_work, ll.strain_work);  // dissipation is part of the strain work
    Real max_eps_p = 0;
    for (const MaterialPoint& p : pl) max_eps_p = std::max(max_eps_p, p.plastic_strain);
    EXPECT_GT(max_eps_p, 0.0);
    // the yielded moments are smaller than the elastic ones
    EXPECT_LT(ll.bending_moment.norm(), le.bending_moment.norm());
}

// The fully plastic moment each thickness rule integrates (theory.md §4.5, §7.3): a flat
// element bent about y step by step (kxx grows, kyy = 0, no membrane strain) far beyond yield
// in a perfectly plastic J2 material reaches at every point off the mid-surface the limit of
// plane strain in y, sigma_xx = 2 sigma_y / sqrt(3) (sigma_yy = sigma_xx / 2), so
//   M_xx = h^2 / 4 * sum_k w_k |zeta_k| * 2 sigma_y / sqrt(3),
// the closed form of the rule: 2 Gauss points (LS-DYNA's default NIP 2) 2 / sqrt(3) of the exact
// M_p = h^2 / 4 * 2 sigma_y / sqrt(3), 3 Lobatto points 2 / 3 of it, 5 Lobatto points 0.913.
// Every rule of quadrature.hpp (Gauss 1-10, Lobatto 3-10, a user rule of 4 equal layers).
TEST(ShellTriangle, EachThicknessRuleIntegratesItsFullyPlasticMoment) {
    const std::array<Vec3, 3> base{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 0.8, 0)};
    const Real h = 0.05, e = 200e9, nu = 0.3, sigma_y = 250e6;
    // an increment of uniform curvature kxx = k, as in SectionResultantsMatchPlateTheory
    const Real k = 2e-3 * sigma_y / (e * h);  // 1/1000 of the surface's yield curvature per step
    const Real c = (-k / 2 * 0.09 + k / 2 * 0.3) / 0.8;
    std::array<Vec3, 3> dth;
    for (int i = 0; i < 3; ++i) {
        const Real x = base[i].x();
        dth[i] = Vec3(-c, -(-k * x + k / 2), 0);
    }
    FlowStress flow;
    flow.yield_stress = sigma_y;  // perfectly plastic
    const J2Plastic steel(e, nu, flow, RateFactor{}, 1.0);
    const std::array<ThicknessPoint, 4> layers{
        {{-0.75, 0.5}, {-0.25, 0.5}, {0.25, 0.5}, {0.75, 0.5}}};
    std::vector<std::pair<std::string, std::span<const ThicknessPoint>>> rules;
    for (int n = 1; n <= k_max_thickness_points; ++n) {
        rules.emplace_back("Gauss " + std::to_string(n), gauss_thickness_rule(n));
        if (n >= 3) rules.emplace_back("Lobatto " + std::to_string(n), lobatto_thickness_rule(n));
    }
    rules.emplace_back("4 equal layers", layers);
    for (const auto& [name, through] : rules) {
        ShellRule r = rule(BendingKernel::Dkt);
        r.through = through;
        Real sum = 0, inner = 1;  // sum_k w_k |zeta_k|; the smallest |zeta_k| > 0
        for (const ThicknessPoint& p : r.through) {
            sum += p.weight * std::abs(p.zeta);
            if (p.zeta != 0) inner = std::min(inner, std::abs(p.zeta));
        }
        const Real closed_form = h * h / 4 * sum * 2 * sigma_y / std::sqrt(3.0);
        std::vector<MaterialPoint> points(static_cast<std::size_t>(r.n_points()));
        ShellTriangleLoads loads;
        // up to 20 times the yield curvature of the point nearest the mid-surface (40 times the
        // surface's when that is a Gauss point of 2), where its stress is within 1e-6 of its
        // limit; 1 / (sum of 3 in-plane point moments) rounding aside
        const int steps = static_cast<int>(std::ceil(20000 / inner));
        for (int step = 0; step < steps; ++step)
            loads = shell_triangle_loads(reverse_motion(base, base, dth, k_no_drill_axes), r, steel,
                                         points, 0.0);
        if (sum == 0) {  // Gauss 1: the mid-surface point bears no moment (a membrane)
            EXPECT_NEAR(loads.bending_moment(0), 0.0, 1e-9 * h * h * sigma_y) << name;
            continue;
        }
        EXPECT_NEAR(loads.bending_moment(0), closed_form, 1e-4 * closed_form) << name;
    }
    // the rules' own sums: 2 / sqrt(3), 2 / 3, 2 (49/90 sqrt(3/7) + 1/10)
    Real gauss = 0, lobatto3 = 0, lobatto5 = 0;
    for (const ThicknessPoint& p : thickness_rule(2)) gauss += p.weight * std::abs(p.zeta);
    for (const ThicknessPoint& p : thickness_rule(3)) lobatto3 += p.weight * std::abs(p.zeta);
    for (const ThicknessPoint& p : thickness_rule(5)) lobatto5 += p.weight * std::abs(p.zeta);
    EXPECT_NEAR(gauss, 2 / std::sqrt(3.0), 1e-15);
    EXPECT_NEAR(lobatto3, 2.0 / 3.0, 1e-15);
    EXPECT_NEAR(lobatto5, 2 * (49.0 / 90.0 * std::sqrt(3.0 / 7.0) + 0.1), 1e-15);
}
