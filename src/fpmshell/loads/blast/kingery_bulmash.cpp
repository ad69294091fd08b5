#include "fpmshell/loads/blast/kingery_bulmash.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

namespace fpmshell {

namespace {

// The report's own units: Z in ft/lb^(1/3), pressures in psi, impulses in psi ms/lb^(1/3),
// times in ms/lb^(1/3); converted to SI once evaluated.
constexpr Real k_feet_per_metre = 3.280839895013123;
constexpr Real k_pounds_per_kilogram = 2.2046226218487757;
constexpr Real k_pascals_per_psi = 6894.757293168361;
const Real k_cube_root_pounds = std::cbrt(k_pounds_per_kilogram);
const Real k_scaled_feet_per_scaled_metre = k_feet_per_metre / k_cube_root_pounds;
constexpr Real k_sound_speed = 340.29;  ///< m/s, sea-level air (the 1/Z wave beyond the fits)

/// One fit: log10 Y = sum_i c_i U^i, U = a + b log10 Z, for Z (ft/lb^(1/3)) in [low, high].
struct Fit {
    Real low, high, a, b;
    std::vector<Real> c;
};

/// A quantity: its fits in order of Z.
using Piecewise = std::vector<Fit>;

Real evaluate(const Piecewise& q, Real z_feet) {
    const Fit* f = &q.front();
    for (const Fit& g : q)
        if (z_feet >= g.low) f = &g;
    const Real z = std::clamp(z_feet, q.front().low, q.back().high);
    const Real u = f->a + f->b * std::log10(z);
    Real y = 0;  // Horner's scheme from the highest power
    for (auto c = f->c.rbegin(); c != f->c.rend(); ++c) y = y * u + *c;
    return std::pow(10.0, y);
}

struct Quantities {
    Piecewise incident_pressure, reflected_pressure, incident_impulse, reflected_impulse,
        arrival_time, duration;
};

// Kingery & Bulmash 1984, spherical free-air burst: the report's imperial coefficients to nine
// digits (checked against the values of benchmarks.md §6.2 within 0.1 %,
// test_kingery_bulmash.cpp)
const Quantities& free_air() {
    static const Quantities q{
        {{0.134,
          100,
          -0.756579302,
          1.3503425,
          {1.772849705, -1.690128014, 0.008049736, 0.336743115, -0.005162264, -0.080922862,
           -0.004785073, 0.007930305, 0.000768447}}},
        {{0.134,
          100,
          -0.756579302,
          1.3503425,
          {2.391061349, -2.21400539, 0.035119031, 0.657599992, 0.014181895, -0.243076636,
           -0.01586998, 0.049274118, 0.002276396, -0.003971263}}},
        {{0.134,
          2,
          1.045048777,
          3.242990665,
          {1.435341365, -0.443749378, 0.168825415, 0.034813803, -0.010435193}},
         {2,
          100,
          -2.679125195,
          2.306292318,
          {0.599008468, -0.404632921, -0.014272195, 0.009123663, -0.000675068, -0.008008637,
           0.003148195, 0.001520448, -0.000747027}}},
        {{0.134,
          100,
          -0.75765992,
          1.37882996,
          {1.605792801, -0.903118886, 0.101771878, -0.024213975}}},
        {{0.134,
          100,
          -0.805017341,
          1.374070438,
          {-0.042373394, 1.364568712, -0.057003569, -0.182832225, 0.011885144, 0.043264869,
           -0.000799737, -0.004360736}}},
        {{0.37,
          2.24,
          0.20944006,
          5.115885543,
          {-0.801052723, 0.164953518, 0.127788499, 0.002914301, 0.001879574, 0.017341396,
           0.002697398, -0.003619765, -0.001009266}},
         {2.24,
          5.75,
          -5.067784938,
          9.299628861,
          {0.115874238, -0.029794427, 0.030632954, 0.018340557, -0.017396467, -0.00106322,
           0.0056206, 0.000161822, -0.000686019}},
         {5.75,
          100,
          -4.395901341,
          3.152472536,
          {0.506592104, 0.0967032, -0.008013021, 0.004827058, 0.001875873, -0.002467385,
           -0.000841117, 0.000619329}}}};
    return q;
}

// Kingery & Bulmash 1984, hemispherical surface burst (checked as free_air's, within 0.6 %)
const Quantities& surface() {
    static const Quantities q{
        {{0.17,
          100,
          -0.756579302,
          1.3503425,
          {1.942250201, -1.695898874, -0.154159377, 0.514060731, 0.098853437, -0.293912623,
           -0.026811235, 0.109097496, 0.001628468, -0.021463103, 0.000145672, 0.001678478}}},
        {{0.17,
          100,
          -0.789312406,
          1.366377192,
          {2.564313211, -2.210308706, -0.218536586, 0.895319589, 0.249890098, -0.569249437,
           -0.117916824, 0.224131161, 0.024562026, -0.0455116, -0.001909307, 0.003614712}}},
        {{0.17,
          2.41,
          0.832468843,
          3.076032967,
          {1.571592406, -0.502992764, 0.171335645, 0.045017696, -0.011896463}},
         {2.41,
          100,
          -2.913586168,
          2.406977454,
          {0.719852656, -0.384519027, -0.026081671, 0.005957988, 0.014544526, -0.006632893,
           -0.002841893, 0.001364482}}},
        {{0.17,
          100,
          -0.781951689,
          1.334220499,
          {1.752916778, -0.949516093, 0.112136119, -0.025065918}}},
        {{0.17,
          100,
          -0.755684473,
          1.377842236,
          {-0.173607601, 1.357064963, 0.052492799, -0.196563954, -0.060177005, 0.069636027,
           0.021529749, -0.016165893, -0.00232532, 0.001477521}}},
        {{0.45,
          2.54,
          -0.179021705,
          5.250991939,
          {-0.728671776, 0.130143718, 0.134872512, 0.039157428, -0.004759337, -0.004281446}},
         {2.54,
          7,
          -5.859098123,
          9.299628861,
          {0.200965073, -0.029794427, 0.030632954, 0.018340557, -0.017396467, -0.00106322,
           0.0056206, 0.000161822, -0.000686019}},
         {7,
          100,
          -4.926994911,
          3.463497456,
          {0.57246247, 0.09330353, -0.000584942, -0.00226885, -0.002959086, 0.001480299}}}};
    return q;
}

}  // namespace

Real kingery_bulmash_min_distance(BlastBurst burst) {
    return (burst == BlastBurst::FreeAir ? 0.134 : 0.17) / k_scaled_feet_per_scaled_metre;
}

BlastWave kingery_bulmash(BlastBurst burst, Real mass, Real distance) {
    const Quantities& q = burst == BlastBurst::FreeAir ? free_air() : surface();
    const Real cube_root_mass = std::cbrt(mass);
    const Real z = distance / cube_root_mass;  // m/kg^(1/3)
    const Real z_fit = std::min(z, k_kingery_bulmash_max_distance);
    const Real z_feet = z_fit * k_scaled_feet_per_scaled_metre;
    // eq. 6.13-2 beyond the fits: 1/Z decay of the peaks and impulses, the front at c
    const Real decay = z > z_fit ? z_fit / z : 1.0;
    const Real impulse_unit = k_pascals_per_psi * 1e-3 * k_cube_root_pounds * cube_root_mass;
    const Real time_unit = 1e-3 * k_cube_root_pounds * cube_root_mass;
    BlastWave w;
    w.incident_pressure = decay * k_pascals_per_psi * evaluate(q.incident_pressure, z_feet);
    w.reflected_pressure = decay * k_pascals_per_psi * evaluate(q.reflected_pressure, z_feet);
    w.incident_impulse = decay * impulse_unit * evaluate(q.incident_impulse, z_feet);
    w.reflected_impulse = decay * impulse_unit * evaluate(q.reflected_impulse, z_feet);
    w.arrival_time =
        time_unit * evaluate(q.arrival_time, z_feet) + (z - z_fit) * cube_root_mass / k_sound_speed;
    w.duration = time_unit * evaluate(q.duration, z_feet);
    return w;
}

}  // namespace fpmshell
