// Thresholds on a point's stress and strain (failure/thresholds/, theory.md eq. 7.6-5, LS-DYNA's
// *MAT_ADD_EROSION): on homogeneous paths whose in-plane strain the motion prescribes (log
// strain ln(1 + t) of the stretch 1 + t), the plate erodes when the threshold is passed:
// - each strain threshold (effective, major and minor principal, volumetric, shear, thinning)
//   at the total strain of the path, its through-thickness part from the point's stress
//   (elastic) and plastic incompressibility, within 1 %;
// - the stress thresholds at the point's stress; NCS = 2 waits for the later of two; a failure
//   time erodes at that time whatever the state.
#include <gtest/gtest.h>

#include <cmath>

#include "fpmshell/failure/thresholds/thresholds_failure.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "homogeneous_paths.hpp"

namespace fpmshell {
namespace {

constexpr Real k_e = 2.0e11, k_nu = 0.3;  // the plate's steel (homogeneous_paths.hpp)

/// The total strain tensor of a point on the equibiaxial (biaxial) or plane-strain path at
/// time t with plane stress s: [xx, yy, zz] principal (no shear on these paths).
std::array<Real, 3> path_strain(bool biaxial, Real t, const Voigt3& s) {
    const Real l = std::log1p(t);
    const Real exx = l, eyy = biaxial ? l : 0.0;
    const Real elastic_xx = (s[0] - k_nu * s[1]) / k_e, elastic_yy = (s[1] - k_nu * s[0]) / k_e;
    const Real ezz = -k_nu * (s[0] + s[1]) / k_e - (exx - elastic_xx) - (eyy - elastic_yy);
    return {exx, eyy, ezz};
}

/// What a threshold measures of a principal strain tensor.
Real effective(const std::array<Real, 3>& e) {
    const Real v = (e[0] + e[1] + e[2]) / 3;
    return std::sqrt(2.0 / 3.0 *
                     ((e[0] - v) * (e[0] - v) + (e[1] - v) * (e[1] - v) + (e[2] - v) * (e[2] - v)));
}
Real major(const std::array<Real, 3>& e) { return std::max({e[0], e[1], e[2]}); }
Real minor(const std::array<Real, 3>& e) { return std::min({e[0], e[1], e[2]}); }
Real shear(const std::array<Real, 3>& e) { return 0.5 * (major(e) - minor(e)); }
Real volume(const std::array<Real, 3>& e) { return e[0] + e[1] + e[2]; }
Real thinning(const std::array<Real, 3>& e) { return -e[2]; }

/// Runs the path until every element has eroded; returns the measure `of` the path's strain,
/// and the point's stress, at the step before the first erosion and at the last one, and the
/// time of the first.
struct Crossing {
    Real before = 0, at = 0;
    Voigt3 stress_before = Voigt3::Zero(), stress_at = Voigt3::Zero();
    Real time = 0;
};
template <class Measure>
Crossing first_erosion(const test::HomogeneousPath& path, const ThresholdsFailureParameters& p,
                       bool biaxial, const Measure& of) {
    const Model m = test::damaging_path(path.velocity, path.lateral_free, {"thresholds", p});
    ExplicitSolver s(m);
    Crossing c;
    while (s.eroded_elements() < m.n_elements() && s.time() < 1) {
        const Voigt3 stress = s.elements().point_state(0, 0).stress;
        if (s.eroded_elements() == 0) {  // the state of the step before the first erosion
            c.before = of(path_strain(biaxial, s.time(), stress));
            c.stress_before = stress;
        }
        s.step(1e30);
        if (s.eroded_elements() > 0 && c.time == 0) c.time = s.time();
    }
    // the state the last element eroded at (the elements share it to rounding)
    c.stress_at = s.elements().point_state(0, 0).stress;
    c.at = of(path_strain(biaxial, s.time(), c.stress_at));
    EXPECT_EQ(s.eroded_elements(), m.n_elements());
    return c;
}

TEST(ThresholdsFailure, StrainThresholdsErodeAtThePathsTotalStrain) {
    const std::vector<test::HomogeneousPath> paths = test::homogeneous_paths();
    struct Case {
        const char* name;
        std::optional<Real> ThresholdsFailureParameters::*key;
        Real value;
        Real (*measure)(const std::array<Real, 3>&);
    };
    const Case cases[] = {
        {"effective", &ThresholdsFailureParameters::max_effective_strain, 0.2, effective},
        {"major", &ThresholdsFailureParameters::max_principal_strain, 0.1, major},
        {"minor", &ThresholdsFailureParameters::min_principal_strain, -0.15, minor},
        {"shear", &ThresholdsFailureParameters::max_shear_strain, 0.1, shear},
        {"thinning", &ThresholdsFailureParameters::thinning_strain, 0.08, thinning},
        // elastic only: (1 - 2 nu) (sxx + syy) / E, 2.5e-4 near the yield stress (equibiaxial)
        {"volumetric", &ThresholdsFailureParameters::volumetric_strain, 5e-4, volume}};
    for (const bool biaxial : {true, false}) {
        const test::HomogeneousPath& path = paths[biaxial ? 0 : 1];
        for (const Case& c : cases) {
            SCOPED_TRACE(std::string(path.name) + ", " + c.name);
            ThresholdsFailureParameters p;
            p.*(c.key) = c.value;
            const auto [before, at, sb, sa, time] = first_erosion(path, p, biaxial, c.measure);
            const Real v = std::abs(c.value);
            const Real sign = c.value < 0 ? -1.0 : 1.0;
            // not passed before, passed at the erosion: within 1 % (the criterion sums the
            // plastic strain along the step's end direction; a step's increment)
            EXPECT_LT(sign * before, v * 1.01);
            EXPECT_GT(sign * at, v * 0.99);
            EXPECT_GT(time, 0.0);
        }
    }
}

TEST(ThresholdsFailure, StressThresholdsAndTheirCountAndTheTime) {
    const test::HomogeneousPath uniaxial = test::homogeneous_paths()[2];
    const auto von_mises = [](const Voigt3& s) {
        return std::sqrt(s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3 * s[2] * s[2]);
    };
    const auto none = [](const std::array<Real, 3>&) { return 0.0; };
    {  // von Mises 3.0e8: the hardening line (yield 2.5e8, H 1e9) passes it at alpha ~ 0.05
        ThresholdsFailureParameters p;
        p.max_von_mises_stress = 3.0e8;
        const Crossing c = first_erosion(uniaxial, p, false, none);
        EXPECT_LT(von_mises(c.stress_before), 3.0e8);
        EXPECT_GE(von_mises(c.stress_at), 3.0e8);
    }
    {  // the pressure in tension, -sxx / 3 <= -0.9e8
        ThresholdsFailureParameters p;
        p.min_pressure = -0.9e8;
        const Crossing c = first_erosion(uniaxial, p, false, none);
        EXPECT_GT(-(c.stress_before[0] + c.stress_before[1]) / 3, -0.9e8);
        EXPECT_LE(-(c.stress_at[0] + c.stress_at[1]) / 3, -0.9e8);
    }
    // NCS = 2: the principal stress 2.6e8 is passed long before the major strain 0.15
    Real later = 0, strain_alone = 0;
    for (const int conditions : {2, 1}) {
        ThresholdsFailureParameters p;
        p.max_principal_stress = 2.6e8;
        if (conditions == 2) p.max_principal_strain = 0.15;
        p.conditions = conditions;
        (conditions == 2 ? later : strain_alone) = first_erosion(uniaxial, p, false, none).time;
    }
    EXPECT_GT(later, 0.15);                // at least the time of ln(1 + t) = 0.15 minus elastic
    EXPECT_LT(strain_alone, 0.5 * later);  // the stress alone erodes far earlier
    {  // a failure time: at the first step that ends at or after it, the state elastic
        ThresholdsFailureParameters p;
        p.time = 1e-3;
        const Crossing c = first_erosion(uniaxial, p, false, none);
        EXPECT_GE(c.time, 1e-3);
        EXPECT_LT(c.time, 1e-3 + 1e-4);
    }
}

}  // namespace
}  // namespace fpmshell
