// Plane-stress J2 plasticity (theory.md §7): return mapping against closed-form answers and
// an independent 3-D algorithm.
// - a random non-proportional path of 60 increments equals the 3-D radial return with the
//   sigma_33 = 0 condition solved by bisection (tools/theory_checks/test_j2.py);
// - after every plastic increment the stress lies on the yield surface;
// - equibiaxial and pure-shear paths against their closed-form elastic-plastic answers, for any
//   increment size (proportional paths: backward Euler is exact);
// - hardening limits: isotropic (beta = 1) reverses at -sigma_max, kinematic (beta = 0) at
//   sigma_max - 2 sigma_y (Bauschinger);
// - non-proportional paths converge as the increments shrink;
// - Johnson-Cook flow curve; Cowper-Symonds and Johnson-Cook rate factors against their formulas;
// - a tabulated flow curve: equibiaxial paths against the curve in every segment, past its
//   last point and across several points in one increment; a tabulated straight line is the
//   bilinear material on a random path;
// - plastic work = integral of sigma . d eps_p.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "fpmshell/materials/j2/j2_plastic.hpp"

using namespace fpmshell;

namespace {

constexpr Real k_e = 200e3, k_nu = 0.3, k_sy = 250.0;

J2Plastic bilinear(Real hardening, Real beta, RateFactor rate = {}) {
    FlowStress f;
    f.yield_stress = k_sy;
    f.hardening = hardening;
    return J2Plastic(k_e, k_nu, f, rate, beta);
}

Real yield_function(const J2Plastic& m, const MaterialPoint& p) {
    const Voigt3 x = p.stress - p.back_stress;
    const Real s = x(0) + x(1), d = x(1) - x(0);
    const Real j2x2 = s * s / 6.0 + 0.5 * d * d + 2.0 * x(2) * x(2);
    const Real k = m.yield_radius(p.plastic_strain, 1.0);
    return 0.5 * j2x2 - k * k / 3.0;
}

/// Applies n equal increments of the total strain increment total.
MaterialPoint apply(const J2Plastic& m, MaterialPoint p, const Voigt3& total, int n, Real dt = 0) {
    for (int i = 0; i < n; ++i) m.update(p, total / n, dt, p);
    return p;
}

}  // namespace

TEST(J2Plastic, RandomPathMatchesThreeDimensionalReturnWithZeroSigma33) {
    // tools/theory_checks/j2_path_reference.py: E 200e3, nu 0.3, sigma_y 250, H_iso 1000, H_kin
    // 800, i.e. H = 1800 and beta = 1000/1800 here; the reference is an independent 3-D radial
    // return.
    const std::vector<std::array<Real, 3>> path{
        {0.0010755374812200385, 0.00020636352235224199, -9.5314103002985985e-05},
        {0.00060713340023437075, 9.0197770948868161e-06, -0.00011407903505950284},
        {0.0010270388712278181, -0.00015734981913685805, -2.8083655017173024e-05},
        {0.00086670563156402499, 0.00032649030815626816, 5.6242269808683074e-06},
        {0.00062547027551976308, 0.00020464336332577917, 0.00014204279601039794},
        {0.00060040507308995253, 0.00032779700477459208, 0.00057934257124518369},
        {0.0010481737887972718, 0.00032173276035166615, -0.00022782291681680084},
        {0.00098386539860810291, 0.00031907063037439479, 0.0002207807182985295},
        {0.00077771417236217075, -0.00031943903354530735, -7.8993797455459571e-05},
        {0.00088870957875504129, 0.00033040884259031861, 0.00055992764132491049},
        {0.00078160782124217368, 0.00029224794221731208, -0.00028740922752964869},
        {0.0010440222616104179, 3.8959443068471436e-05, -0.00058314995980317719},
        {0.00097576374912316339, -8.0941166220585008e-05, 0.00038981397257787959},
        {0.00093452256098548075, -0.00039908574454845737, -7.7065602416104263e-06},
        {0.0010940822203942247, -0.00020487129849029444, -0.00020975476470313191},
        {0.0010963769856869238, -0.00024714632679808757, 8.1012888744806227e-05},
        {0.00059089274289217614, 0.00037403220023211469, 0.00036381536313584401},
        {0.00075837565714845635, -0.0003356433451579717, -0.00021593447439294508},
        {0.00080635251401645915, 0.0003462670593815254, -0.00046913058488267555},
        {0.00084101379687244102, 0.00016524912789351172, 5.6929093594108507e-05},
        {-0.00034842650936693116, 3.2226885576259167e-05, 0.00055660625516856105},
        {-0.00051745149763089357, 7.0093651340349082e-05, -6.6013168469380583e-05},
        {-0.00052297051073351493, -9.2079083221871638e-05, 9.0781216997866206e-05},
        {-0.00076773639807779358, -0.00024848693715651512, -0.00037592456609333386},
        {-0.00050978145610511456, 0.00012532751119170306, -2.8162809588743086e-05},
        {-0.00092814051104352503, 0.00020608313757314943, 0.00045212444498732968},
        {-0.00026129518724297539, 0.00027396817851214596, 0.00047780774562945473},
        {-0.00026153404814385848, 3.2479939958443537e-05, -0.00013044473971845014},
        {-0.00043577328011647491, -0.00017949270295029827, 0.00037395445020945415},
        {-0.00032041122785090627, 0.00031603117394134021, 0.0001077614202373918},
        {-0.00024018810141430351, 6.3756008596484734e-05, -5.9324272042613788e-05},
        {-0.00047180369710208875, 0.00039700627148285821, 0.00050032946153694721},
        {-0.00036533993269582059, -0.00033410160944268209, 0.00013533972604885464},
        {-0.00061084463842466647, 0.00010411787232917824, 0.00041409309080581819},
        {-0.00080557150235051496, 0.00018519137663267822, -0.00045943884814977838},
        {-0.00082363157050573718, 0.00023566637736846074, -0.00020095662093641342},
        {-0.00034726952277307232, -0.00031951398382712307, -0.00042436981330523535},
        {-0.0004418634878470089, -0.00036381274570751015, 8.8639244147000295e-05},
        {-0.0002719871882407682, 2.7358374608579174e-05, 0.00021670695907470778},
        {-0.00097864256427023584, 0.00010799992792916662, 0.0001276061013050627},
        {-0.00053923764157476741, -8.7032472541738503e-05, -0.000155832071597775},
        {-0.00021558667948218501, -0.00037088636991081136, -0.00057403618817397108},
        {-0.00023117497580831101, -0.00025202244688204934, -0.00045132580269068191},
        {-0.0008315387920906828, 0.00024059727228334477, 0.00052436299037349687},
        {-0.00098177393946507325, -5.9504934426546276e-05, -0.00047819973675099626},
        {-0.00079206408816573435, -0.00022333658294694612, 0.00017631086380238704},
        {-0.00071976482608277414, -0.00025574567877624971, 4.3638062518646762e-06},
        {-0.00096849703433224605, -0.00031926300704882671, 0.00058588217846700119},
        {-0.00084051536762634951, -0.00011315575895071852, 0.00027791796747043268},
        {-0.00032933874784526687, 0.00033478564959626517, -0.00039669047268303876},
        {-0.00046188754914155787, 0.00037323912243454659, -0.00053033886740820157},
        {-0.00045903857256049732, 0.00027633967496129314, -0.00018922495070569919},
        {-0.00079945012857191066, 7.7433114775528819e-05, -6.9223159561105252e-05},
        {-0.00086014441243884704, -2.2699667922969626e-05, -0.0001081135252109345},
        {-0.0005447098083805758, 6.8801040501065284e-06, -0.00022626479879975182},
        {-0.00071427865392778968, 0.00027012893949518321, -0.0002988808022134355},
        {-0.00055151982491718078, -0.00039005094493654852, 0.00028988925289279627},
        {-0.00073126675642123148, -0.00036344280514526671, -0.00026294020293798209},
        {-0.00080789567373891675, 0.00036250347186223914, -0.00017732932618139106},
        {-0.00076969766811488, -0.00011263904219700295, 0.00053628700278946927},
    };
    const J2Plastic m = bilinear(1800.0, 1000.0 / 1800.0);
    struct Check {
        int step;
        Voigt3 sigma, b;
        Real alpha;
    };
    const Check checks[] = {
        {19,
         {326.652905378, 193.256296188, -7.57758024678},
         {17.7078778253, 9.68714141271, 0.0481116629908},
         0.01945563751},
        {39,
         {-309.971928121, -160.153586202, 7.38405816909},
         {10.3994110576, 7.19445345796, 0.475475390574},
         0.0277999843741},
        {59,
         {-341.531337848, -173.555763614, 14.1747532577},
         {-3.80409577237, -0.393860428807, 0.0456980895026},
         0.0435338708895},
    };
    MaterialPoint p;
    std::size_t c = 0;
    for (int step = 0; step < static_cast<int>(path.size()); ++step) {
        const auto& d = path[static_cast<std::size_t>(step)];
        m.update(p, Voigt3(d[0], d[1], d[2]), 0.0, p);
        if (p.plastic_strain > 0) {
            // on or inside the surface: |f| within the Newton tolerance (1e-10 kappa^2/3)
            EXPECT_LT(yield_function(m, p), 1e-9 * k_sy * k_sy);
        }
        if (c < std::size(checks) && checks[c].step == step) {
            // 12 printed digits of the reference; Newton stops at 1e-10: 1e-8 of the stress
            for (int i = 0; i < 3; ++i) {
                EXPECT_NEAR(p.stress(i), checks[c].sigma(i), 1e-8 * 400) << "step " << step;
                EXPECT_NEAR(p.back_stress(i), checks[c].b(i), 1e-8 * 400) << "step " << step;
            }
            EXPECT_NEAR(p.plastic_strain, checks[c].alpha, 1e-9);
            ++c;
        }
    }
    EXPECT_EQ(c, std::size(checks));
}

TEST(J2Plastic, StressStaysOnYieldSurfaceForRandomIncrements) {
    for (Real beta : {0.0, 0.5, 1.0}) {
        const J2Plastic m = bilinear(500.0, beta);
        std::mt19937 rng(7);
        std::uniform_real_distribution<Real> u(-3e-3, 3e-3);
        MaterialPoint p;
        int plastic_steps = 0;
        for (int i = 0; i < 500; ++i) {
            const Real alpha_before = p.plastic_strain;
            m.update(p, Voigt3(u(rng), u(rng), u(rng)), 0.0, p);
            if (p.plastic_strain > alpha_before) {
                ++plastic_steps;
                // Newton tolerance 1e-10 of kappa^2/3; kappa grows with alpha
                const Real k = m.yield_radius(p.plastic_strain, 1.0);
                EXPECT_NEAR(yield_function(m, p), 0.0, 1e-9 * k * k)
                    << "beta " << beta << " step " << i;
            } else {
                EXPECT_LE(yield_function(m, p), 1e-9 * k_sy * k_sy);
            }
        }
        EXPECT_GT(plastic_steps, 100);  // the path must exercise the return
    }
}

TEST(J2Plastic, EquibiaxialPathMatchesClosedFormForAnyIncrement) {
    // eps11 = eps22 = eps: sigma11 = sigma22 = s = sigma_eq; elastic s = E eps / (1 - nu);
    // plastic: eps = s (1 - nu) / E + alpha / 2 with s = sigma_y + H alpha.
    const Real h = 2000.0;
    const J2Plastic m = bilinear(h, 1.0);
    const Real eps = 0.01;
    const Real alpha = (eps - k_sy * (1 - k_nu) / k_e) / ((1 - k_nu) * h / k_e + 0.5);
    const Real s = k_sy + h * alpha;
    for (int n : {1, 7, 1000}) {
        const MaterialPoint p = apply(m, MaterialPoint{}, Voigt3(eps, eps, 0), n);
        // proportional loading: exact up to the Newton tolerance and round-off
        EXPECT_NEAR(p.stress(0), s, 1e-8 * s) << n << " increments";
        EXPECT_NEAR(p.stress(1), s, 1e-8 * s);
        EXPECT_NEAR(p.stress(2), 0.0, 1e-9 * s);
        EXPECT_NEAR(p.plastic_strain, alpha, 1e-9);
    }
}

TEST(J2Plastic, UniaxialStressPathMatchesClosedForm) {
    // eps11 driven, eps22 chosen at every increment so that sigma22 = 0 (bisection on a copy of
    // the point): sigma = sigma_y + H eps_p with eps11 = sigma / E + eps_p past yield.
    const Real h = 3000.0;
    const J2Plastic m = bilinear(h, 1.0);
    MaterialPoint p;
    const int n = 400;
    const Real eps_total = 0.02, de = eps_total / n;
    for (int i = 0; i < n; ++i) {
        Real lo = -de, hi = de;  // d eps22 lies between -d eps11 and +d eps11
        for (int it = 0; it < 200; ++it) {
            const Real mid = 0.5 * (lo + hi);
            MaterialPoint trial = p;
            m.update(p, Voigt3(de, mid, 0), 0.0, trial);
            (trial.stress(1) > 0 ? hi : lo) = mid;
        }
        m.update(p, Voigt3(de, 0.5 * (lo + hi), 0), 0.0, p);
    }
    const Real eps_p = (eps_total - k_sy / k_e) / (1.0 + h / k_e);
    const Real sigma = k_sy + h * eps_p;
    // sigma22 = 0 to the bisection's precision; the path is proportional once plastic, so the
    // answer is exact to round-off: 1e-7 relative
    EXPECT_NEAR(p.stress(1), 0.0, 1e-6 * sigma);
    EXPECT_NEAR(p.stress(0), sigma, 1e-7 * sigma);
    EXPECT_NEAR(p.plastic_strain, eps_p, 1e-7 * eps_p);
    // W_p = sigma_y eps_p + H eps_p^2 / 2: the trapezoidal rule is exact on the linear
    // hardening branch; the increment crossing the yield point is off by at most half of one
    // increment's plastic strain (5e-5 of 0.0199: 0.13 %)
    EXPECT_NEAR(p.plastic_work, k_sy * eps_p + 0.5 * h * eps_p * eps_p, 2e-3 * k_sy * eps_p);
}

TEST(J2Plastic, PureShearPathMatchesClosedForm) {
    // gamma only: xi = [0, 0, tau], sigma_eq = sqrt(3) tau; gamma = tau / G + sqrt(3) alpha with
    // sqrt(3) tau = sigma_y + H alpha. Perfect plasticity: tau = sigma_y / sqrt(3) exactly.
    const Real g = k_e / (2 * (1 + k_nu));
    const Real gamma = 0.02;
    for (Real h : {0.0, 3000.0}) {
        const J2Plastic m = bilinear(h, 1.0);
        const Real alpha =
            (gamma - k_sy / (std::sqrt(3.0) * g)) / (h / (std::sqrt(3.0) * g) + std::sqrt(3.0));
        const Real tau = (k_sy + h * alpha) / std::sqrt(3.0);
        for (int n : {1, 50}) {
            const MaterialPoint p = apply(m, MaterialPoint{}, Voigt3(0, 0, gamma), n);
            EXPECT_NEAR(p.stress(2), tau, 1e-8 * tau) << "H " << h << ", " << n << " increments";
            EXPECT_NEAR(p.stress(0), 0.0, 1e-9 * tau);
            EXPECT_NEAR(p.plastic_strain, alpha, 1e-9);
            // perfectly plastic: all the work past yield is dissipated, W_p = tau gamma_p; the
            // trapezoidal rule is exact once yielded, the increment that crosses the yield
            // point is not (at most half of it: 1 % of the plastic strain with 50 increments)
            if (h == 0 && n == 50) {
                EXPECT_NEAR(p.plastic_work, tau * std::sqrt(3.0) * alpha,
                            0.01 * tau * std::sqrt(3.0) * alpha);
            }
        }
    }
}

TEST(J2Plastic, HardeningLimitsReverseYieldPoint) {
    // Equibiaxial load to s_max, then reverse in small steps: the first plastic step of the
    // reversal comes at -s_max (isotropic, beta = 1) or at s_max - 2 sigma_y (kinematic, beta = 0).
    const Real h = 5000.0;
    for (Real beta : {1.0, 0.0}) {
        const J2Plastic m = bilinear(h, beta);
        MaterialPoint p = apply(m, MaterialPoint{}, Voigt3(0.006, 0.006, 0), 60);
        const Real s_max = p.stress(0);
        const Real expected = beta == 1.0 ? -s_max : s_max - 2.0 * k_sy;
        const Real d = -1e-6;  // stress step E d / (1 - nu) = 0.29 per step
        Real reverse_at = 0;
        for (int i = 0; i < 20000; ++i) {
            const Real alpha_before = p.plastic_strain;
            const Real s_before = p.stress(0);
            m.update(p, Voigt3(d, d, 0), 0.0, p);
            if (p.plastic_strain > alpha_before) {
                reverse_at = s_before;
                break;
            }
        }
        // within one elastic stress step (0.29) of the exact point
        EXPECT_NEAR(reverse_at, expected, 0.3) << "beta " << beta;
    }
}

TEST(J2Plastic, NonProportionalPathConvergesWithSmallerIncrements) {
    // Equibiaxial stretch, then shear: the answer depends on the increment size (non-
    // proportional), and converges at first order as it shrinks.
    const J2Plastic m = bilinear(1500.0, 0.5);
    auto run = [&](int n) {
        MaterialPoint p = apply(m, MaterialPoint{}, Voigt3(0.004, 0.004, 0), n);
        return apply(m, p, Voigt3(0, 0, 0.01), n);
    };
    const MaterialPoint coarse = run(2), medium = run(20), fine = run(2000);
    const Real e_coarse = (coarse.stress - fine.stress).norm(),
               e_medium = (medium.stress - fine.stress).norm();
    EXPECT_GT(e_coarse, 1e-3 * fine.stress.norm());  // the path effect is real
    EXPECT_LT(e_medium, 0.2 * e_coarse);             // 10x smaller steps: about 10x smaller error
}

TEST(J2Plastic, JohnsonCookFlowCurveOnMonotonicPath) {
    // Equibiaxial with sigma = A + B alpha^n: eps = s (1 - nu) / E + alpha / 2.
    FlowStress f;
    f.kind = FlowStress::Kind::JohnsonCook;
    f.a = 350.0;
    f.b = 275.0;
    f.n = 0.36;
    const J2Plastic m(k_e, k_nu, f, RateFactor{}, 1.0);
    for (Real alpha : {0.001, 0.05, 0.3}) {
        const Real s = f.a + f.b * std::pow(alpha, f.n);
        const Real eps = s * (1 - k_nu) / k_e + 0.5 * alpha;
        const MaterialPoint p = apply(m, MaterialPoint{}, Voigt3(eps, eps, 0), 40);
        EXPECT_NEAR(p.plastic_strain, alpha, 1e-8 * (1 + alpha)) << "alpha " << alpha;
        EXPECT_NEAR(p.stress(0), s, 1e-8 * s);
    }
}

// Equibiaxial with sigma = sigma_f(alpha) piecewise linear: eps = s (1 - nu) / E + alpha / 2,
// exact for any number of increments (proportional path), in every kind of segment: hardening,
// flat (perfectly plastic), past the last point (its last segment extended), and reached in one
// increment across several points.
TEST(J2Plastic, TabulatedFlowCurveOnMonotonicPath) {
    const FlowStress f = FlowStress::tabulated({0.0, 0.002, 0.01, 0.05, 0.08, 0.2},
                                               {250.0, 290.0, 330.0, 380.0, 380.0, 430.0});
    const J2Plastic m(k_e, k_nu, f, RateFactor{}, 1.0);
    for (Real alpha : {0.001, 0.006, 0.03, 0.06, 0.15, 0.3}) {
        const Real s = f.value(alpha);
        const Real eps = s * (1 - k_nu) / k_e + 0.5 * alpha;
        for (int n : {1, 7, 400}) {
            const MaterialPoint p = apply(m, MaterialPoint{}, Voigt3(eps, eps, 0), n);
            // the Newton tolerance |F| < 1e-10 kappa^2 / 3: 1e-10 relative in the stress
            EXPECT_NEAR(p.plastic_strain, alpha, 1e-8 * (1 + alpha))
                << "alpha " << alpha << ", " << n << " increments";
            EXPECT_NEAR(p.stress(0), s, 1e-8 * s);
            EXPECT_NEAR(p.stress(1), s, 1e-8 * s);
            // the stored radius and slope are the curve's at the new plastic strain
            EXPECT_NEAR(p.flow_radius, s, 1e-8 * s);
            EXPECT_EQ(p.flow_slope, f.slope(p.plastic_strain));
        }
    }
    // the last segment, extended (to rounding: the slope is stored, not the two points)
    EXPECT_NEAR(f.value(0.3), 430.0 + (430.0 - 380.0) / 0.12 * 0.1, 1e-12 * 430.0);
    EXPECT_EQ(f.slope(0.06), 0.0);
    EXPECT_EQ(f.slope(0.0), 40.0 / 0.002);
}

namespace {

/// Materials `a` and `b` give the same states along a random non-proportional path with
/// unloading (seed `seed`) that goes well past yield: the iterates of their returns agree to
/// the Newton tolerance, 1e-10 relative.
void expect_same_states_on_a_random_path(const J2Plastic& a, const J2Plastic& b, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    MaterialPoint pa, pb;
    for (int i = 0; i < 200; ++i) {
        const Voigt3 d(2e-3 * u(rng), 2e-3 * u(rng), 2e-3 * u(rng));
        a.update(pa, d, 0.0, pa);
        b.update(pb, d, 0.0, pb);
        for (Eigen::Index k = 0; k < 3; ++k) ASSERT_NEAR(pa.stress(k), pb.stress(k), 1e-8 * k_sy);
        ASSERT_NEAR(pa.plastic_strain, pb.plastic_strain, 1e-10 + 1e-8 * pa.plastic_strain);
    }
    EXPECT_GT(pa.plastic_strain, 0.05) << "the path must go well past yield";
}

}  // namespace

// A power law (eq. 7.2-6) on the equibiaxial path: sigma = k (eps_0 + alpha)^n, and with n = 1
// it is the bilinear curve of yield stress k eps_0 and plastic modulus k, state for state
// along a random non-proportional path with unloading.
TEST(J2Plastic, PowerLawOnMonotonicPathAndAsBilinear) {
    FlowStress f;
    f.kind = FlowStress::Kind::PowerLaw;
    f.b = 600.0;
    f.n = 0.3;
    f.strain_offset = std::pow(k_sy / f.b, 1.0 / f.n);
    EXPECT_NEAR(f.value(0.0), k_sy, 1e-12 * k_sy);
    const J2Plastic m(k_e, k_nu, f, RateFactor{}, 1.0);
    for (Real alpha : {0.001, 0.05, 0.3}) {
        const Real s = f.b * std::pow(f.strain_offset + alpha, f.n);
        const Real eps = s * (1 - k_nu) / k_e + 0.5 * alpha;
        for (int n : {1, 40}) {
            const MaterialPoint p = apply(m, MaterialPoint{}, Voigt3(eps, eps, 0), n);
            EXPECT_NEAR(p.plastic_strain, alpha, 1e-8 * (1 + alpha)) << "alpha " << alpha;
            EXPECT_NEAR(p.stress(0), s, 1e-8 * s);
            EXPECT_NEAR(p.flow_slope, f.slope(p.plastic_strain), 1e-12 * f.slope(0.0));
        }
    }
    const Real h = 2000.0;
    FlowStress line;
    line.kind = FlowStress::Kind::PowerLaw;
    line.b = h;
    line.n = 1.0;
    line.strain_offset = k_sy / h;
    // the same curve through pow(x, 0) = 1
    for (Real beta : {1.0, 0.5, 0.0})
        expect_same_states_on_a_random_path(bilinear(h, beta),
                                            J2Plastic(k_e, k_nu, line, RateFactor{}, beta), 5);
}

// A tabulated straight line is the bilinear curve: the same states along a random
// non-proportional path with unloading, for isotropic, mixed and kinematic hardening.
TEST(J2Plastic, TabulatedStraightLineIsTheBilinearMaterial) {
    const Real h = 2000.0;
    // the same operations but for the curve's evaluation (one segment, exact slope h)
    for (Real beta : {1.0, 0.5, 0.0})
        expect_same_states_on_a_random_path(
            bilinear(h, beta),
            J2Plastic(k_e, k_nu, FlowStress::tabulated({0.0, 1.0}, {k_sy, k_sy + h}), RateFactor{},
                      beta),
            3);
}

// A table of two curves (eq. 7.2-5), equibiaxial at a constant rate (the filter settled): the
// stress lies on the curve interpolated between them at the rate's position, the first curve
// below their rates and the last above.
TEST(J2Plastic, RateTableGivesTheCurveOfTheRate) {
    const std::vector<Real> rates{10.0, 1000.0};
    // sigma = 250 + 1000 alpha at 10 /s, 300 + 2000 alpha (to 0.05, then flat) at 1000 /s
    RateFactor table;
    table.kind = RateFactor::Kind::Table;
    table.table_rates = rates;
    const J2Plastic m(
        k_e, k_nu,
        FlowStress::tabulated({PiecewiseLinearCurve({0.0, 1.0}, {250.0, 1250.0}),
                               PiecewiseLinearCurve({0.0, 0.05, 1.0}, {300.0, 400.0, 400.0})},
                              rates),
        table, 1.0);
    const Real dt = 1e-6;
    for (Real eps_dot : {2.0, 100.0, 250.0, 5000.0}) {
        const Real rate = 2.0 * eps_dot;  // the effective rate of equibiaxial straining
        const int n = 1000;               // 0.02 x eps_dot / 100 total strain; filter settled
        const Real eps = eps_dot * dt * n;
        const MaterialPoint p = apply(m, MaterialPoint{}, Voigt3(eps, eps, 0), n, dt);
        ASSERT_NEAR(p.strain_rate, rate, 1e-9 * rate);
        const Real w = std::clamp((rate - 10.0) / 990.0, 0.0, 1.0);
        const Real a = p.plastic_strain;
        ASSERT_GT(a, 0.0) << "rate " << rate;
        const Real expected =
            (1 - w) * (250.0 + 1000.0 * a) + w * (a < 0.05 ? 300.0 + 2000.0 * a : 400.0);
        EXPECT_NEAR(p.stress(0), expected, 1e-8 * expected) << "rate " << rate;
        EXPECT_NEAR(p.stress(1), expected, 1e-8 * expected);
        // the stored radius: the first curve's, which the element's trial check reads
        EXPECT_NEAR(p.flow_radius, 250.0 + 1000.0 * a, 1e-9 * expected);
    }
}

TEST(J2Plastic, RateFactorsFollowTheirFormulas) {
    // Perfectly plastic, equibiaxial at a constant rate: effective rate 2 eps_dot; after many
    // increments (filter settled) sigma = sigma_y R(rate).
    const Real eps_dot = 50.0, dt = 1e-6;
    const Real rate = 2.0 * eps_dot;
    RateFactor cs;
    cs.kind = RateFactor::Kind::CowperSymonds;
    cs.d = 40.4;
    cs.q = 5.0;
    RateFactor jc;
    jc.kind = RateFactor::Kind::JohnsonCook;
    jc.c = 0.022;
    jc.reference_rate = 1.0;
    for (const RateFactor& r : {cs, jc}) {
        const J2Plastic m = bilinear(0.0, 1.0, r);
        const Real expected = k_sy * (r.kind == RateFactor::Kind::CowperSymonds
                                          ? 1.0 + std::pow(rate / cs.d, 1.0 / cs.q)
                                          : 1.0 + jc.c * std::log(rate / jc.reference_rate));
        const int n = 400;  // 0.02 total strain; the filter (memory 10 steps) has settled
        const MaterialPoint p =
            apply(m, MaterialPoint{}, Voigt3(eps_dot * dt * n, eps_dot * dt * n, 0), n, dt);
        EXPECT_NEAR(p.strain_rate, rate, 1e-9 * rate);
        EXPECT_NEAR(p.stress(0), expected, 1e-7 * expected);
    }
    // below the reference rate Johnson-Cook gives no softening (rate factor clamped at 1)
    EXPECT_DOUBLE_EQ(jc.value(0.5), 1.0);
    EXPECT_DOUBLE_EQ(cs.value(0.0), 1.0);
}

// A curve of the factor against the rate (LS-DYNA's *MAT_024 LCSR, eq. 7.4-3): piecewise linear
// through its points, its end segments going on past them; every lane of a pack its scalar; and
// the stress of a perfectly plastic equibiaxial path at a constant rate, sigma_y R(rate).
TEST(J2Plastic, RateScalingCurveGivesTheFactorOfTheRate) {
    RateFactor curve;
    curve.kind = RateFactor::Kind::Curve;
    curve.scaling = PiecewiseLinearCurve({0.0, 50.0, 200.0}, {1.0, 1.2, 1.5});
    EXPECT_DOUBLE_EQ(curve.value(0.0), 1.0);
    EXPECT_DOUBLE_EQ(curve.value(50.0), 1.2);
    EXPECT_NEAR(curve.value(100.0), 1.3, 1e-15);
    EXPECT_NEAR(curve.value(300.0), 1.7, 1e-15);  // the last segment goes on
    RealPack rates(0.0);
    for (int l = 0; l < k_lanes; ++l) set_lane(rates, l, 37.0 * l);
    const RealPack factors = curve.value(rates);
    for (int l = 0; l < k_lanes; ++l) EXPECT_EQ(lane(factors, l), curve.value(37.0 * l));
    const Real eps_dot = 50.0, dt = 1e-6, rate = 2.0 * eps_dot;
    const J2Plastic m = bilinear(0.0, 1.0, curve);
    const int n = 400;  // 0.02 total strain; the filter (memory 10 steps) has settled
    const MaterialPoint p =
        apply(m, MaterialPoint{}, Voigt3(eps_dot * dt * n, eps_dot * dt * n, 0), n, dt);
    EXPECT_NEAR(p.strain_rate, rate, 1e-9 * rate);
    EXPECT_NEAR(p.stress(0), k_sy * 1.3, 1e-7 * k_sy);
}

TEST(J2Plastic, ElasticRangeIsLinearElastic) {
    const J2Plastic m = bilinear(1000.0, 1.0);
    const Voigt3 d(2e-4, -1e-4, 3e-4);
    const MaterialPoint p = apply(m, MaterialPoint{}, d, 3);
    const Voigt3 expected = m.stiffness() * d;
    EXPECT_LT((p.stress - expected).norm(), 1e-12 * expected.norm());
    EXPECT_EQ(p.plastic_strain, 0.0);
    EXPECT_EQ(p.plastic_work, 0.0);
}
