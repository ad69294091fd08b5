// The SIMD block kernel of the elastic DKT triangle (elements/elastic_triangle_block.hpp)
// against the general scalar element (reverse_motion + shell_triangle_loads):
// - on random path elements of a stable step (any orientation, rotations of the step below
//   0.01 rad, random old stresses, with and without stiffness damping), every lane of the
//   pack and the T = Real instance give the scalar element's loads, stresses, work and L_c;
// - a rigid motion gives zero loads on every lane;
// - a rate-independent J2 section: lanes whose points all stay elastic give the scalar J2
//   element's result; a lane with one point whose trial state yields is reported invalid;
// - lanes outside the kernel's bounds (a step rotation over 0.01 rad, a tilt over 90 deg,
//   a collapsed triangle) are reported invalid and the others stay valid.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "fpmshell/core/rotation.hpp"
#include "fpmshell/elements/elastic_triangle_block.hpp"
#include "fpmshell/elements/shell_triangle.hpp"
#include "fpmshell/materials/elastic/linear_elastic.hpp"
#include "fpmshell/materials/j2/j2_plastic.hpp"

using namespace fpmshell;

namespace {

constexpr Real k_young = 200e9, k_poisson = 0.3, k_thickness = 0.01;

struct PathElement {
    std::array<Vec3, 3> base, current, dtheta;
    std::array<Vec3, 3> drill_axis = k_no_drill_axes;
    std::vector<Voigt3> stress;  // old stresses, [g][k]
};

ShellRule make_rule(int inplane, std::span<const ThicknessPoint> through,
                    BendingKernel bending = BendingKernel::Dkt) {
    ShellRule r;
    r.thickness = k_thickness;
    r.inplane = triangle_rule(inplane);
    r.through = through;
    r.bending = bending;
    return r;
}

ElasticSectionConstants constants_of(const LinearElastic& m, const ShellRule& r) {
    ElasticSectionConstants c;
    c.c11 = m.stiffness()(0, 0);
    c.c12 = m.stiffness()(0, 1);
    c.c33 = m.stiffness()(2, 2);
    c.thickness_factor = (1.0 - 2.0 * m.poisson_ratio()) / m.youngs_modulus();
    c.inplane = r.inplane;
    c.through = r.through;
    c.bending = r.bending;
    return c;
}

/// A path element of a stable step: a random triangle of size ~1 in a random orientation,
/// moved rigidly by a rotation of `step_rotation` rad and a translation, deformed by nodal
/// displacements ~1e-3 (strains ~1e-3) and relative nodal rotations ~2e-4 (bending). Nodes 1
/// and 2 rotate in a tangent plane of their own (a drill axis within ~20 deg of the element
/// normal, as on a curved shell), node 3 by a complete increment (as a kink).
PathElement random_path_element(std::mt19937& rng, int n_points, Real step_rotation) {
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    auto rvec = [&] { return Vec3(u(rng), u(rng), u(rng)); };
    PathElement p;
    const Mat3 orientation = rotation_matrix(3.0 * rvec());
    const std::array<Vec3, 3> flat{Vec3(0, 0, 0), Vec3(1.0 + 0.3 * u(rng), 0.1 * u(rng), 0),
                                   Vec3(0.4 + 0.3 * u(rng), 0.8 + 0.2 * u(rng), 0)};
    const Vec3 origin = 10.0 * rvec();
    const Vec3 phi = step_rotation * rvec().normalized();
    const Mat3 r = rotation_matrix(phi);
    for (std::size_t i = 0; i < 3; ++i) {
        p.base[i] = origin + orientation * flat[i];
        p.current[i] =
            r * (p.base[i] - origin) + origin + Vec3(0.002, -0.001, 0.003) + 1e-3 * rvec();
        p.dtheta[i] = phi + 2e-4 * rvec();  // rigid rotation + bending
    }
    const Vec3 normal = orientation.col(2);
    for (std::size_t i = 0; i < 2; ++i) {
        const Vec3 d = (normal + 0.3 * rvec()).normalized();
        p.drill_axis[i] = d;
        p.dtheta[i] -= p.dtheta[i].dot(d) * d;
    }
    p.stress.resize(static_cast<std::size_t>(n_points));
    for (Voigt3& s : p.stress) s = 1e8 * Voigt3(u(rng), u(rng), u(rng));
    return p;
}

template <class T>
TriangleMotion<T> motion_of(const std::array<const PathElement*, k_lanes>& lanes) {
    TriangleMotion<T> m;
    auto pack = [&](auto&& value) {
        if constexpr (std::is_same_v<T, Real>) {
            return value(0);
        } else {
            return T([&](auto l) { return value(static_cast<int>(l)); });
        }
    };
    for (std::size_t i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c) {
            const auto pick = [&](const std::array<Vec3, 3> PathElement::*field) {
                return pack(
                    [&](int l) { return (lanes[static_cast<std::size_t>(l)]->*field)[i](c); });
            };
            T* base[3] = {&m.base[i].x, &m.base[i].y, &m.base[i].z};
            T* cur[3] = {&m.current[i].x, &m.current[i].y, &m.current[i].z};
            T* dth[3] = {&m.dtheta[i].x, &m.dtheta[i].y, &m.dtheta[i].z};
            T* drill[3] = {&m.drill_axis[i].x, &m.drill_axis[i].y, &m.drill_axis[i].z};
            *base[c] = pick(&PathElement::base);
            *cur[c] = pick(&PathElement::current);
            *dth[c] = pick(&PathElement::dtheta);
            *drill[c] = pick(&PathElement::drill_axis);
        }
    return m;
}

struct Reference {
    ShellTriangleLoads loads;
    std::vector<MaterialPoint> points;
    Real characteristic_length;
};

Reference scalar_reference(const PathElement& p, const ShellRule& rule, const LinearElastic& mat,
                           Real viscous_rate) {
    Reference ref;
    for (const Voigt3& s : p.stress) {
        MaterialPoint mp;
        mp.stress = s;
        ref.points.push_back(mp);
    }
    ref.loads = shell_triangle_loads(reverse_motion(p.base, p.current, p.dtheta, p.drill_axis),
                                     rule, mat, ref.points, viscous_rate);
    const Vec3 e1 = p.current[1] - p.current[0], e2 = p.current[2] - p.current[1],
               e3 = p.current[0] - p.current[2];
    ref.characteristic_length =
        e1.cross(p.current[2] - p.current[0]).norm() /
        std::sqrt(std::max({e1.squaredNorm(), e2.squaredNorm(), e3.squaredNorm()}));
    return ref;
}

/// |a - b| <= tol * scale, componentwise.
void expect_close(const Vec3& a, const Vec3& b, Real scale, Real tol, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a(c), b(c), tol * scale) << what << " component " << c;
}

// Tolerance: the kernel sums a few products in another order than Eigen does (and may fuse
// them into FMAs), so each result differs by some ulps of its largest term. The largest
// amplification is the reverse motion, where the deformation displacements (~1e-3) are
// differences of positions (~10): 1e-16 x 1e4 = 1e-12 of the strain, hence 1e-9 relative to
// the largest load of the element leaves two orders of margin and still catches any wrong term
// (a wrong coefficient changes the loads at the 1e-2 level or more).
constexpr Real k_rel_tol = 1e-9;

template <class T>
void check_against_scalar(std::uint32_t seed, int inplane, std::span<const ThicknessPoint> through,
                          Real viscous_rate, BendingKernel bending = BendingKernel::Dkt) {
    std::mt19937 rng(seed);
    const ShellRule rule = make_rule(inplane, through, bending);
    const LinearElastic mat(k_young, k_poisson);
    const ElasticSectionConstants constants = constants_of(mat, rule);
    const int n_points = rule.n_points();
    constexpr int n_lanes = std::is_same_v<T, Real> ? 1 : k_lanes;
    std::vector<PathElement> elements;
    for (int l = 0; l < k_lanes; ++l) elements.push_back(random_path_element(rng, n_points, 0.004));
    std::array<const PathElement*, k_lanes> lanes;
    for (int l = 0; l < k_lanes; ++l)
        lanes[static_cast<std::size_t>(l)] = &elements[static_cast<std::size_t>(l)];
    const TriangleMotion<T> motion = motion_of<T>(lanes);
    std::vector<T> stress(static_cast<std::size_t>(3 * n_points));
    for (int p = 0; p < n_points; ++p)
        for (int r = 0; r < 3; ++r) {
            if constexpr (std::is_same_v<T, Real>) {
                stress[static_cast<std::size_t>(3 * p + r)] =
                    elements[0].stress[static_cast<std::size_t>(p)](r);
            } else {
                stress[static_cast<std::size_t>(3 * p + r)] =
                    T([&](auto l) { return elements[l].stress[static_cast<std::size_t>(p)](r); });
            }
        }
    const T thickness(k_thickness);
    const ElasticTriangleLoads<T> out =
        elastic_triangle_loads(motion, constants, thickness, stress.data(), viscous_rate);
    for (int l = 0; l < n_lanes; ++l) {
        SCOPED_TRACE(::testing::Message() << "seed " << seed << " lane " << l);
        const Reference ref =
            scalar_reference(elements[static_cast<std::size_t>(l)], rule, mat, viscous_rate);
        ASSERT_TRUE(lane(out.valid, l));
        Real f_scale = 0, m_scale = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            f_scale = std::max(f_scale, ref.loads.force[i].norm());
            m_scale = std::max(m_scale, ref.loads.moment[i].norm());
        }
        ASSERT_GT(f_scale, 1e3);  // the case is not trivially zero
        // a rule with points off the mid-surface bends (Gauss 1 carries no moment: m_scale 0)
        if (std::any_of(through.begin(), through.end(), [](auto& p) { return p.zeta != 0; }))
            ASSERT_GT(m_scale, 1e1);
        else
            ASSERT_EQ(m_scale, 0.0);
        for (std::size_t i = 0; i < 3; ++i) {
            expect_close(
                Vec3(lane(out.force[i].x, l), lane(out.force[i].y, l), lane(out.force[i].z, l)),
                ref.loads.force[i], f_scale, k_rel_tol, "force");
            expect_close(
                Vec3(lane(out.moment[i].x, l), lane(out.moment[i].y, l), lane(out.moment[i].z, l)),
                ref.loads.moment[i], m_scale, k_rel_tol, "moment");
        }
        Real s_scale = 0;
        for (const MaterialPoint& mp : ref.points)
            s_scale = std::max(s_scale, mp.stress.cwiseAbs().maxCoeff());
        for (int p = 0; p < n_points; ++p)
            for (int r = 0; r < 3; ++r)
                EXPECT_NEAR(lane(stress[static_cast<std::size_t>(3 * p + r)], l),
                            ref.points[static_cast<std::size_t>(p)].stress(r), k_rel_tol * s_scale);
        const Real n_scale = ref.loads.membrane_force.cwiseAbs().maxCoeff();
        const Real mb_scale = ref.loads.bending_moment.cwiseAbs().maxCoeff();
        for (std::size_t r = 0; r < 3; ++r) {
            EXPECT_NEAR(lane(out.membrane_force[r], l),
                        ref.loads.membrane_force(static_cast<Eigen::Index>(r)),
                        k_rel_tol * n_scale);
            EXPECT_NEAR(lane(out.bending_moment[r], l),
                        ref.loads.bending_moment(static_cast<Eigen::Index>(r)),
                        k_rel_tol * mb_scale);
        }
        // work: a sum of terms of either sign, compared to the size of its largest term
        const Real work_scale = 0.5 * s_scale * 1e-3 * k_thickness;
        EXPECT_NEAR(lane(out.strain_work, l), ref.loads.strain_work, k_rel_tol * work_scale);
        EXPECT_NEAR(lane(out.damping_work, l), ref.loads.damping_work,
                    k_rel_tol * std::abs(ref.loads.damping_work) + 1e-300);
        EXPECT_NEAR(lane(out.thickness_strain, l), ref.loads.thickness_strain,
                    1e-12);  // strains ~1e-3: 1e-9 relative, as above
        EXPECT_NEAR(lane(out.characteristic_length, l), ref.characteristic_length,
                    1e-15 * ref.characteristic_length);
    }
}

}  // namespace

TEST(ElasticTriangleBlock, PackLanesMatchTheScalarElement) {
    for (std::uint32_t seed = 1; seed <= 20; ++seed)
        check_against_scalar<RealPack>(seed, 3, thickness_rule(2), 0.0);
}

TEST(ElasticTriangleBlock, ScalarInstanceMatchesTheScalarElement) {
    for (std::uint32_t seed = 1; seed <= 20; ++seed)
        check_against_scalar<Real>(seed, 3, thickness_rule(2), 0.0);
}

TEST(ElasticTriangleBlock, OtherRulesAndStiffnessDamping) {
    check_against_scalar<RealPack>(31, 7, thickness_rule(5), 0.0);  // Radon 7 x Lobatto 5
    // Radon 7 x Gauss 10, the largest rule; Lobatto 4, Gauss 1 (no moment), a user rule
    check_against_scalar<RealPack>(34, 7, gauss_thickness_rule(10), 0.0);
    check_against_scalar<RealPack>(35, 3, lobatto_thickness_rule(4), 0.0);
    check_against_scalar<RealPack>(36, 3, gauss_thickness_rule(1), 0.0);
    const std::array<ThicknessPoint, 3> layers{{{-0.6, 0.5}, {0.1, 0.9}, {0.8, 0.6}}};
    check_against_scalar<RealPack>(37, 3, layers, 0.0);
    check_against_scalar<RealPack>(32, 3, thickness_rule(3), 0.0);
    check_against_scalar<RealPack>(33, 3, thickness_rule(2),
                                   2e-3);  // a_s / dt of a typical damped run
}

TEST(ElasticTriangleBlock, BcizLanesMatchTheScalarElement) {
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        check_against_scalar<RealPack>(seed, 3, thickness_rule(2), 0.0, BendingKernel::Bciz);
        check_against_scalar<Real>(seed, 3, thickness_rule(2), 0.0, BendingKernel::Bciz);
    }
    check_against_scalar<RealPack>(41, 7, thickness_rule(5), 2e-3, BendingKernel::Bciz);
}

TEST(ElasticTriangleBlock, RigidMotionGivesZeroLoadsOnEveryLane) {
    std::mt19937 rng(7);
    const ShellRule rule = make_rule(3, thickness_rule(2));
    const LinearElastic mat(k_young, k_poisson);
    const ElasticSectionConstants constants = constants_of(mat, rule);
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    std::vector<PathElement> elements(k_lanes);
    for (PathElement& p : elements) {
        const Vec3 phi = 0.009 * Vec3(u(rng), u(rng), u(rng)).normalized();
        const Mat3 r = rotation_matrix(phi);
        const Vec3 shift(u(rng), u(rng), u(rng));
        p.base = {Vec3(u(rng), u(rng), u(rng)), Vec3(1.5, 0.2, 0.1), Vec3(0.3, 1.1, -0.2)};
        for (std::size_t i = 0; i < 3; ++i) {
            p.current[i] = r * p.base[i] + 1e-2 * shift;
            p.dtheta[i] = phi;
        }
    }
    std::array<const PathElement*, k_lanes> lanes;
    for (int l = 0; l < k_lanes; ++l)
        lanes[static_cast<std::size_t>(l)] = &elements[static_cast<std::size_t>(l)];
    std::vector<RealPack> stress(static_cast<std::size_t>(3 * rule.n_points()), RealPack(0.0));
    const auto out = elastic_triangle_loads(motion_of<RealPack>(lanes), constants,
                                            RealPack(k_thickness), stress.data(), 0.0);
    for (int l = 0; l < k_lanes; ++l) {
        ASSERT_TRUE(lane(out.valid, l));
        // E h = 2e9: a force of 1e-3 N is a strain of 5e-13, round-off of positions ~1
        for (std::size_t i = 0; i < 3; ++i) {
            EXPECT_NEAR(lane(out.force[i].x, l), 0.0, 1e-3);
            EXPECT_NEAR(lane(out.force[i].y, l), 0.0, 1e-3);
            EXPECT_NEAR(lane(out.force[i].z, l), 0.0, 1e-3);
            EXPECT_NEAR(lane(out.moment[i].x, l), 0.0, 1e-6);
            EXPECT_NEAR(lane(out.moment[i].y, l), 0.0, 1e-6);
            EXPECT_NEAR(lane(out.moment[i].z, l), 0.0, 1e-6);
        }
    }
}

TEST(ElasticTriangleBlock, LanesOutsideTheBoundsAreReportedInvalid) {
    std::mt19937 rng(11);
    const ShellRule rule = make_rule(3, thickness_rule(2));
    const LinearElastic mat(k_young, k_poisson);
    const ElasticSectionConstants constants = constants_of(mat, rule);
    std::vector<PathElement> elements;
    for (int l = 0; l < k_lanes; ++l)
        elements.push_back(random_path_element(rng, rule.n_points(), 0.004));
    // lane 0: a nodal rotation increment of 0.05 rad (beyond the series branch)
    elements[0].dtheta[1] += Vec3(0.05, 0, 0);
    // lane 1: the current triangle flipped over (tilt of 180 deg)
    std::swap(elements[1].current[1], elements[1].current[2]);
    std::array<const PathElement*, k_lanes> lanes;
    for (int l = 0; l < k_lanes; ++l)
        lanes[static_cast<std::size_t>(l)] = &elements[static_cast<std::size_t>(l)];
    if constexpr (k_lanes > 2) {
        // lane 2: a collapsed current triangle (all nodes on a line)
        elements[2].current[2] = 0.5 * (elements[2].current[0] + elements[2].current[1]);
    }
    std::vector<RealPack> stress(static_cast<std::size_t>(3 * rule.n_points()), RealPack(0.0));
    const auto out = elastic_triangle_loads(motion_of<RealPack>(lanes), constants,
                                            RealPack(k_thickness), stress.data(), 0.0);
    const int n_bad = k_lanes > 2 ? 3 : 2;
    for (int l = 0; l < k_lanes; ++l) EXPECT_EQ(lane(out.valid, l), l >= n_bad) << "lane " << l;
}

namespace {

/// The section's material: yield stress 1e9, far above the random stresses (~1e8) and their
/// increments (~2e8), hardening slope 2e9, mixed hardening, and the rate factor `rate`.
J2Plastic bilinear_j2(const RateFactor& rate) {
    FlowStress flow;
    flow.yield_stress = 1e9;
    flow.hardening = 2e9;
    return J2Plastic(k_young, k_poisson, flow, rate, 0.5);
}

/// The same yield stress and slope at rate 0 in a table of two curves (eq. 7.2-5), the second
/// at 1e4 /s 10 % higher: at the ~1e3 /s of these elements a lane sits a tenth of the way.
J2Plastic rate_table_j2() {
    const std::vector<Real> rates{0.0, 1e4};
    FlowStress flow = FlowStress::tabulated({PiecewiseLinearCurve({0.0, 1.0}, {1e9, 3e9}),
                                             PiecewiseLinearCurve({0.0, 1.0}, {1.1e9, 3.3e9})},
                                            rates);
    RateFactor rate;
    rate.kind = RateFactor::Kind::Table;
    rate.table_rates = rates;
    return J2Plastic(k_young, k_poisson, flow, rate, 1.0);
}

/// mat: the section's material (bilinear_j2 or rate_table_j2); dt: duration of the path
/// element (for the strain rate). with_return_mapping: the yielding point of lane 1 goes to a
/// return mapping (the general J2 update on a copy of the lane's points) and the lane stays
/// valid; without, it is invalid.
void check_j2_lanes(const J2Plastic& mat, Real dt, bool with_return_mapping,
                    std::span<const ThicknessPoint> through = thickness_rule(5)) {
    std::mt19937 rng(23);
    const ShellRule rule = make_rule(3, through);
    const LinearElastic elastic(k_young, k_poisson);
    ElasticSectionConstants constants = constants_of(elastic, rule);
    const int n_points = rule.n_points();
    std::vector<PathElement> elements;
    for (int l = 0; l < k_lanes; ++l) elements.push_back(random_path_element(rng, n_points, 0.004));
    // every lane's points carry a back stress; lane 1's point 4 starts at a shear stress of
    // 1.2e9 (outside the yield surface of radius 1e9 / sqrt 3 in shear): it yields in this
    // step. The points of lane 0 have yielded before: their yield radius is the stored one.
    std::vector<std::vector<MaterialPoint>> old_points(k_lanes);
    std::vector<RealPack> stress(static_cast<std::size_t>(3 * n_points)),
        back(static_cast<std::size_t>(3 * n_points)), third_k2(static_cast<std::size_t>(n_points));
    for (int l = 0; l < k_lanes; ++l)
        for (int p = 0; p < n_points; ++p) {
            MaterialPoint mp;
            mp.stress = elements[static_cast<std::size_t>(l)].stress[static_cast<std::size_t>(p)];
            mp.back_stress = 0.1 * mp.stress;
            if (l == 1 && p == 4) mp.stress(2) = -1.2e9;
            mp.strain_rate = 50.0 * (1 + p);
            if (l == 0) {  // kappa / R, or a table's first curve
                mp.plastic_strain = 0.01;
                mp.flow_radius =
                    mat.yield_radius(0.01, mat.rate_factor().selects_curve() ? 0.0 : 1.0);
                mp.flow_slope = 2e9;
            }
            old_points[static_cast<std::size_t>(l)].push_back(mp);
        }
    for (int p = 0; p < n_points; ++p) {
        auto mp = [&](auto l) -> const MaterialPoint& {
            return old_points[l][static_cast<std::size_t>(p)];
        };
        for (int r = 0; r < 3; ++r) {
            stress[static_cast<std::size_t>(3 * p + r)] =
                RealPack([&](auto l) { return mp(l).stress(r); });
            back[static_cast<std::size_t>(3 * p + r)] =
                RealPack([&](auto l) { return mp(l).back_stress(r); });
        }
        third_k2[static_cast<std::size_t>(p)] = RealPack([&](auto l) {
            const Real kappa =
                mp(l).plastic_strain > 0 ? mp(l).flow_radius : mat.initial_flow_radius();
            return kappa * kappa / 3.0;
        });
    }
    std::vector<RealPack> strain_rate(static_cast<std::size_t>(n_points)),
        new_strain_rate(static_cast<std::size_t>(n_points));
    for (int p = 0; p < n_points; ++p)
        strain_rate[static_cast<std::size_t>(p)] = RealPack(
            [&](auto l) { return old_points[l][static_cast<std::size_t>(p)].strain_rate; });
    YieldSurfaces<RealPack> yield{back.data(), third_k2.data(), J2Plastic::k_yield_tolerance};
    if (mat.rate_dependent()) {
        yield.rate = &mat.rate_factor();
        yield.strain_rate = strain_rate.data();
        yield.new_strain_rate = new_strain_rate.data();
        yield.dt = dt;
        yield.rate_filter = J2Plastic::k_rate_filter;
    }
    std::vector<RealPack> plastic_strain(static_cast<std::size_t>(n_points));
    if (mat.rate_factor().selects_curve()) {
        for (int p = 0; p < n_points; ++p)
            plastic_strain[static_cast<std::size_t>(p)] = RealPack(
                [&](auto l) { return old_points[l][static_cast<std::size_t>(p)].plastic_strain; });
        yield.table = &mat.return_constants().flow.table;
        yield.plastic_strain = plastic_strain.data();
    }
    std::array<const PathElement*, k_lanes> lanes;
    for (int l = 0; l < k_lanes; ++l)
        lanes[static_cast<std::size_t>(l)] = &elements[static_cast<std::size_t>(l)];
    std::vector<std::vector<MaterialPoint>> updated =
        old_points;  // what the return mapping changes
    int n_returns = 0;
    // as ShellElements::compute_block, one point at a time: the return mapping of the yielding
    // lanes of a point, kept in the lanes' points
    auto return_mapping = [&](std::size_t n_pts, const RealPack::mask_type* yielding,
                              const std::array<RealPack, 3>* d_eps, const RealPack* rate_factor,
                              RealPack* new_stress, RealPack* d_plastic_work) {
        for (std::size_t p = 0; p < n_pts; ++p) {
            if (!any_lane(yielding[p])) continue;
            J2PointState<RealPack> old;
            auto point = [&](auto l) -> MaterialPoint& {
                return updated[static_cast<std::size_t>(l)][p];
            };
            for (int r = 0; r < 3; ++r) {
                old.stress[static_cast<std::size_t>(r)] =
                    RealPack([&](auto l) { return point(l).stress(r); });
                old.back_stress[static_cast<std::size_t>(r)] =
                    RealPack([&](auto l) { return point(l).back_stress(r); });
            }
            old.plastic_strain = RealPack([&](auto l) { return point(l).plastic_strain; });
            old.flow_radius = RealPack([&](auto l) { return point(l).flow_radius; });
            old.flow_slope = RealPack([&](auto l) { return point(l).flow_slope; });
            const J2Return<RealPack> ret = j2_return_mapping(mat.return_constants(), old, d_eps[p],
                                                             rate_factor[p], yielding[p]);
            for (int l = 0; l < k_lanes; ++l) {
                if (!lane(ret.yielded, l)) continue;
                ++n_returns;
                MaterialPoint& mp = point(l);
                mp.plastic_strain = lane(ret.state.plastic_strain, l);
                mp.plastic_work += lane(ret.plastic_work, l);
                for (std::size_t r = 0; r < 3; ++r)
                    set_lane(new_stress[3 * p + r], l, lane(ret.state.stress[r], l));
                set_lane(d_plastic_work[p], l, lane(ret.plastic_work, l));
            }
        }
    };
    const auto out =
        with_return_mapping
            ? elastic_triangle_loads(motion_of<RealPack>(lanes), constants, RealPack(k_thickness),
                                     stress.data(), 0.0, &yield, return_mapping)
            : elastic_triangle_loads(motion_of<RealPack>(lanes), constants, RealPack(k_thickness),
                                     stress.data(), 0.0, &yield);
    EXPECT_EQ(n_returns, with_return_mapping ? 1 : 0);  // lane 1's point 4 only
    for (int l = 0; l < k_lanes; ++l) {
        SCOPED_TRACE(::testing::Message() << "lane " << l);
        const PathElement& pe = elements[static_cast<std::size_t>(l)];
        std::vector<MaterialPoint> points = old_points[static_cast<std::size_t>(l)];
        const ShellTriangleLoads ref =
            shell_triangle_loads(reverse_motion(pe.base, pe.current, pe.dtheta, pe.drill_axis),
                                 rule, mat, points, 0.0, dt);
        if (l == 1) {
            EXPECT_GT(points[4].plastic_strain, 0.0);  // the scalar element did yield there
            EXPECT_GT(ref.plastic_work, 0.0);
            if (!with_return_mapping) {
                EXPECT_FALSE(lane(out.valid, l));
                continue;
            }
            // the point's whole history as the scalar element left it (the same update)
            EXPECT_NEAR(updated[1][4].plastic_strain, points[4].plastic_strain,
                        k_rel_tol * points[4].plastic_strain);
            EXPECT_NEAR(lane(out.plastic_work, l), ref.plastic_work, k_rel_tol * ref.plastic_work);
        } else {
            EXPECT_EQ(ref.plastic_work, 0.0);
            EXPECT_EQ(lane(out.plastic_work, l), 0.0);
        }
        ASSERT_TRUE(lane(out.valid, l));
        EXPECT_NEAR(lane(out.thickness_strain, l), ref.thickness_strain, 1e-12);
        EXPECT_NEAR(lane(out.strain_work, l), ref.strain_work,
                    k_rel_tol * std::abs(ref.strain_work) + 1e-6);
        Real f_scale = 0;
        for (std::size_t i = 0; i < 3; ++i) f_scale = std::max(f_scale, ref.force[i].norm());
        for (std::size_t i = 0; i < 3; ++i)
            expect_close(
                Vec3(lane(out.force[i].x, l), lane(out.force[i].y, l), lane(out.force[i].z, l)),
                ref.force[i], f_scale, k_rel_tol, "force");
        for (int p = 0; p < n_points; ++p)
            for (int r = 0; r < 3; ++r)
                EXPECT_NEAR(lane(stress[static_cast<std::size_t>(3 * p + r)], l),
                            points[static_cast<std::size_t>(p)].stress(r), k_rel_tol * 1e9);
        if (mat.rate_dependent()) {
            // the filtered rate: ~1e3 /s here, the same sum of squares in another order
            for (int p = 0; p < n_points; ++p)
                EXPECT_NEAR(lane(new_strain_rate[static_cast<std::size_t>(p)], l),
                            points[static_cast<std::size_t>(p)].strain_rate,
                            1e-12 * points[static_cast<std::size_t>(p)].strain_rate);
        }
    }
}

}  // namespace

TEST(ElasticTriangleBlock, J2LanesStayValidOnlyWhileEveryPointIsElastic) {
    check_j2_lanes(bilinear_j2(RateFactor{}), 0.0, false);
}

TEST(ElasticTriangleBlock, J2YieldingPointsGoToTheReturnMapping) {
    check_j2_lanes(bilinear_j2(RateFactor{}), 0.0, true);
    // LS-DYNA's rules of decks: Gauss 10 (the most points), Gauss 3, Lobatto 7
    check_j2_lanes(bilinear_j2(RateFactor{}), 0.0, true, gauss_thickness_rule(10));
    check_j2_lanes(bilinear_j2(RateFactor{}), 0.0, true, gauss_thickness_rule(3));
    check_j2_lanes(bilinear_j2(RateFactor{}), 0.0, true, lobatto_thickness_rule(7));
    RateFactor jc;  // R ~ 1.14: the 1.2e9 shear of lane 1's point 4 still yields
    jc.kind = RateFactor::Kind::JohnsonCook;
    jc.c = 0.02;
    jc.reference_rate = 1.0;
    check_j2_lanes(bilinear_j2(jc), 1e-6, true);
    check_j2_lanes(rate_table_j2(), 1e-6, true);  // the curve of the lane's rate
}

TEST(ElasticTriangleBlock, RateDependentJ2LanesUpdateTheFilteredStrainRate) {
    RateFactor jc;  // Johnson-Cook C = 0.02 at 1 /s: R ~ 1.14 at the ~1e3 /s of this case
    jc.kind = RateFactor::Kind::JohnsonCook;
    jc.c = 0.02;
    jc.reference_rate = 1.0;
    check_j2_lanes(bilinear_j2(jc), 1e-6, false);
    check_j2_lanes(rate_table_j2(), 1e-6, false);
}
