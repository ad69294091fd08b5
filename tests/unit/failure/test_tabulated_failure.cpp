// Damage on a failure strain tabulated against triaxiality, regularized by the element size
// (failure/tabulated/, theory.md eq. 7.6-3): homogeneous paths erode at the table's failure
// strain of their triaxiality, times the regularization factor of the elements' size, times the
// rate scaling's factor of their plastic strain rate.
#include <gtest/gtest.h>

#include <cmath>

#include "fpmshell/failure/tabulated/tabulated_failure.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "homogeneous_paths.hpp"

namespace fpmshell {
namespace {

// the failure strain at the four paths' triaxialities, and between them
TabulatedFailureParameters table() {
    TabulatedFailureParameters p;
    p.failure_strain = {{-1.0 / 3.0, 0.4},
                        {0.0, 0.3},
                        {1.0 / 3.0, 0.2},
                        {1.0 / std::sqrt(3.0), 0.15},
                        {2.0 / 3.0, 0.12}};
    p.exponent = 2;
    return p;
}

TEST(TabulatedFailure, TheTableAndTheRegularizationAreInterpolatedAndHeldPastTheirEnds) {
    TabulatedFailureParameters p = table();
    p.regularization = {{0.1, 1.5}, {0.5, 0.5}};
    const TabulatedFailure f(p);
    EXPECT_DOUBLE_EQ(f.failure_strain(1.0 / 6.0, 0.1), 0.25 * 1.5);
    EXPECT_DOUBLE_EQ(f.failure_strain(-1.0, 0.05), 0.4 * 1.5);  // both held at their ends
    EXPECT_DOUBLE_EQ(f.failure_strain(0.0, 0.25), 0.3 * 1.125);
    EXPECT_DOUBLE_EQ(f.failure_strain(1.0, 9.0), 0.12 * 0.5);
    EXPECT_DOUBLE_EQ(f.damage(0.5), 0.25);  // D = F^n
}

/// The plastic strain of the plate's first point when its last element erodes, and when its
/// first does, on a path.
std::pair<Real, Real> erosion_strains(const test::HomogeneousPath& path,
                                      const TabulatedFailureParameters& p) {
    const Model m = test::damaging_path(path.velocity, path.lateral_free, {"tabulated", p});
    ExplicitSolver s(m);
    Real first = 0;
    while (s.eroded_elements() < m.n_elements() && s.time() < 1) {
        s.step(1e30);
        if (s.eroded_elements() > 0 && first == 0)
            first = s.elements().point_state(0, 0).plastic_strain;
    }
    EXPECT_EQ(s.eroded_elements(), m.n_elements());
    return {first, s.elements().point_state(0, 0).plastic_strain};
}

TEST(TabulatedFailure, HomogeneousPathsErodeAtTheTablesFailureStrain) {
    for (const test::HomogeneousPath& path : test::homogeneous_paths()) {
        SCOPED_TRACE(path.name);
        const TabulatedFailure f(table());
        const Real expected = f.failure_strain(path.eta, 0.25);
        const auto [first, last] = erosion_strains(path, table());
        // within 1 %, as the Johnson-Cook damage's paths (a step's increment, the elements'
        // rounding, the elastic start of the plane-strain path)
        EXPECT_GT(first, 0.99 * expected);
        EXPECT_LT(last, 1.01 * expected);
    }
}

TEST(TabulatedFailure, TheRegularizationScalesTheFailureStrainByTheElementSize) {
    TabulatedFailureParameters p = table();
    p.regularization = {{0.1, 1.5}, {0.5, 0.5}};  // 1.125 at the plate's 0.25 m
    const test::HomogeneousPath uniaxial = test::homogeneous_paths()[2];
    const auto [first, last] = erosion_strains(uniaxial, p);
    EXPECT_GT(first, 0.99 * 0.2 * 1.125);
    EXPECT_LT(last, 1.01 * 0.2 * 1.125);
}

TEST(TabulatedFailure, TheRateScalingScalesTheFailureStrainByThePlasticStrainRate) {
    // GISSMO's LCSRS: the uniaxial path stretches at 1 /s (a constant velocity field, so the
    // plastic strain rate falls from 1 to 0.77 /s by a strain of 0.3); a factor of 1.5 at rates
    // above 0.5 /s puts its failure at 0.3, one of 1 below 5 /s leaves it at 0.2
    const test::HomogeneousPath uniaxial = test::homogeneous_paths()[2];
    TabulatedFailureParameters fast = table();
    fast.rate_scaling = {{0.1, 1.0}, {0.5, 1.5}};
    EXPECT_DOUBLE_EQ(TabulatedFailure(fast).rate_factor(0.3), 1.25);
    EXPECT_DOUBLE_EQ(TabulatedFailure(fast).rate_factor(0.0), 1.0);  // held past the ends
    const auto [first, last] = erosion_strains(uniaxial, fast);
    EXPECT_GT(first, 0.99 * 0.2 * 1.5);
    EXPECT_LT(last, 1.01 * 0.2 * 1.5);
    TabulatedFailureParameters slow = table();
    slow.rate_scaling = {{5.0, 1.0}, {10.0, 1.5}};
    const auto [first_slow, last_slow] = erosion_strains(uniaxial, slow);
    EXPECT_GT(first_slow, 0.99 * 0.2);
    EXPECT_LT(last_slow, 1.01 * 0.2);
    // the rates as logarithms (LS-DYNA's curve whose first rate is negative), interpolated
    // linearly in ln rate: 1.25 at sqrt(0.1 x 0.5)
    TabulatedFailureParameters log_fast = table();
    log_fast.rate_scaling = {{std::log(0.1), 1.0}, {std::log(0.5), 1.5}};
    log_fast.log_rates = true;
    EXPECT_NEAR(TabulatedFailure(log_fast).rate_factor(std::sqrt(0.05)), 1.25, 1e-12);
    EXPECT_DOUBLE_EQ(TabulatedFailure(log_fast).rate_factor(0.0), 1.0);  // ln 0: below them all
    const auto [first_log, last_log] = erosion_strains(uniaxial, log_fast);
    EXPECT_GT(first_log, 0.99 * 0.2 * 1.5);
    EXPECT_LT(last_log, 1.01 * 0.2 * 1.5);
}

}  // namespace
}  // namespace fpmshell
