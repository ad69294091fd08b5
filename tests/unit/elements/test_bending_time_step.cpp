// Critical step of the bending modes of one triangle (bending_time_step.hpp, theory.md §6.2,
// §6.4):
// - the 9-DOF bending stiffness has exactly the 3 rigid modes of a plate (w = plane with the
//   matching rotations) as its null space and is symmetric positive semi-definite;
// - 2 / omega_max equals the independent Python of tools/theory_checks/test_rot.py
//   (K9, lumped mass rho h A / 3, power iteration), for both kernels, two shapes, thin to thick
//   elements and rotary inertia options A and B;
// - with option B the bending step passes below the membrane step L_c / c for thick elements:
//   the case that made a fine quarter mesh of the spherical cap diverge.
#include <gtest/gtest.h>

#include <cmath>

#include "fpmshell/elements/bending_time_step.hpp"

using namespace fpmshell;

namespace {

Mat3 plate_rigidity(Real e, Real nu, Real h) {
    const Real d = e * h * h * h / (12.0 * (1.0 - nu * nu));
    Mat3 db;
    db << d, nu * d, 0, nu * d, d, 0, 0, 0, d * (1.0 - nu) / 2.0;
    return db;
}

const TriangleShape k_equilateral(1.0, 0.5, std::sqrt(3.0) / 2.0);
const TriangleShape k_right(1.0, 0.0, 1.0);

}  // namespace

TEST(BendingStiffness9, RigidPlateModesGiveNoForce) {
    const TriangleShape s(1.7, 0.4, 1.1);
    for (BendingKernel k : {BendingKernel::Bciz, BendingKernel::Dkt}) {
        const Mat99 kb = bending_stiffness_9dof(k, s, plate_rigidity(2.0, 0.3, 0.1));
        // w = a + b x + c y, thx = w,y = c, thy = -w,x = -b (theory.md §4.1)
        for (const auto& [a, b, c] : {std::array<Real, 3>{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}) {
            Eigen::Matrix<Real, 9, 1> v;
            for (int i = 0; i < 3; ++i) {
                v(3 * i) =
                    a + b * s.x[static_cast<std::size_t>(i)] + c * s.y[static_cast<std::size_t>(i)];
                v(3 * i + 1) = c;
                v(3 * i + 2) = -b;
            }
            // relative to the stiffness scale: round-off only
            EXPECT_LT((kb * v).norm(), 1e-12 * kb.norm()) << "kernel " << static_cast<int>(k);
        }
        EXPECT_LT((kb - kb.transpose()).norm(), 1e-14 * kb.norm());
        const Eigen::SelfAdjointEigenSolver<Mat99> eig(kb);
        int zero = 0;
        for (int i = 0; i < 9; ++i) {
            EXPECT_GT(eig.eigenvalues()(i), -1e-12 * kb.norm());
            if (std::abs(eig.eigenvalues()(i)) < 1e-10 * kb.norm()) ++zero;
        }
        EXPECT_EQ(zero, 3) << "only the 3 rigid modes are free (no spurious zero-energy mode)";
    }
}

TEST(BendingCriticalStep, MatchesIndependentPython) {
    // E = 1, nu = 0.3, rho = 1; the reference dt of tools/theory_checks/bending_step_reference.py
    // (power iteration, 3000 iterations, printed to 8 digits).
    struct Case {
        const TriangleShape* shape;
        BendingKernel kernel;
        Real h;
        bool option_b;
        Real dt;
    };
    const Case cases[] = {
        {&k_equilateral, BendingKernel::Dkt, 0.05, false, 0.49681794},
        {&k_equilateral, BendingKernel::Dkt, 0.05, true, 7.02019652},
        {&k_equilateral, BendingKernel::Dkt, 0.5, true, 0.78993564},
        {&k_equilateral, BendingKernel::Dkt, 1.2, true, 0.42454521},
        {&k_equilateral, BendingKernel::Bciz, 0.05, false, 0.56163045},
        {&k_equilateral, BendingKernel::Bciz, 0.5, true, 0.89833570},
        {&k_equilateral, BendingKernel::Bciz, 1.2, true, 0.48427355},
        {&k_right, BendingKernel::Dkt, 0.5, false, 0.50344547},
        {&k_right, BendingKernel::Dkt, 1.2, true, 0.43895926},
        {&k_right, BendingKernel::Bciz, 0.05, true, 6.78359039},
        {&k_right, BendingKernel::Bciz, 0.5, true, 0.74868090},
        {&k_right, BendingKernel::Bciz, 1.2, false, 0.34919116},
    };
    for (const Case& c : cases) {
        const Real area = 0.5 * c.shape->two_area;
        const Real m = c.h * area / 3.0;
        const Real j = m * ((c.option_b ? area / 8.0 : 0.0) + c.h * c.h / 12.0);
        const Real dt =
            bending_critical_dt(c.kernel, *c.shape, plate_rigidity(1.0, 0.3, c.h), m, j);
        // 8 printed digits and a converged power iteration: 1e-6 relative
        EXPECT_NEAR(dt / c.dt, 1.0, 1e-6)
            << "h " << c.h << " kernel " << static_cast<int>(c.kernel);
    }
}

TEST(BendingCriticalStep, GovernsOnlyThickElements) {
    // Equilateral element of side 1: L_c = sqrt(3)/2; c = sqrt(E / rho (1 - nu^2)).
    const Real lc = std::sqrt(3.0) / 2.0;
    const Real membrane_dt = lc / std::sqrt(1.0 / (1.0 - 0.09));
    auto ratio = [&](Real h) {
        const Real area = 0.5 * k_equilateral.two_area;
        const Real m = h * area / 3.0;
        return bending_critical_dt(BendingKernel::Dkt, k_equilateral, plate_rigidity(1.0, 0.3, h),
                                   m, m * (area / 8.0 + h * h / 12.0)) /
               membrane_dt;
    };
    EXPECT_GT(ratio(0.05), 2.0);  // thin: bending never governs (theory.md §6.2)
    EXPECT_GT(ratio(0.2), 2.0);
    EXPECT_LT(ratio(1.0), 0.9);  // h ~ L_c: below the default time_step_scale
}

TEST(BendingCriticalStep, SufficientStepSkipsOnlyWhatCannotGovern) {
    // With `sufficient` (the membrane step), the function may return a lower bound of the step
    // instead of the step, but only when that bound is at least `sufficient`: then
    // min(step, sufficient), all the caller uses, is unchanged.
    const Real lc = std::sqrt(3.0) / 2.0;
    const Real membrane_dt = lc / std::sqrt(1.0 / (1.0 - 0.09));
    int bounded = 0;
    for (const BendingKernel kernel : {BendingKernel::Dkt, BendingKernel::Bciz})
        for (const TriangleShape* shape : {&k_equilateral, &k_right})
            for (const Real h : {0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 2.0}) {
                SCOPED_TRACE(::testing::Message()
                             << "h " << h << " kernel " << static_cast<int>(kernel));
                const Real area = 0.5 * shape->two_area;
                const Real m = h * area / 3.0, j = m * (area / 8.0 + h * h / 12.0);
                const Mat3 db = plate_rigidity(1.0, 0.3, h);
                const Real exact = bending_critical_dt(kernel, *shape, db, m, j);
                const Real fast = bending_critical_dt(kernel, *shape, db, m, j, membrane_dt);
                EXPECT_LE(fast, exact * (1 + 1e-12));  // a lower bound of the step, never above
                EXPECT_EQ(std::min(fast, membrane_dt), std::min(exact, membrane_dt));
                if (fast != exact) {
                    ++bounded;
                    EXPECT_GE(fast, membrane_dt);
                    // the Frobenius norm is within sqrt(6) of lambda_max: the step within 6^(1/4)
                    EXPECT_GE(fast, exact / std::pow(6.0, 0.25) * (1 - 1e-12));
                }
            }
    EXPECT_GE(bounded, 8);  // the thin elements (h / L_c <= 0.23) do skip the eigenproblem
}
