// The air blast's fits and pulse (loads/blast/, theory.md §6.13):
// - the Kingery-Bulmash fits at Z = 0.5, 1, 2, 3, 5, 10 m/kg^(1/3) within 1 % of the values
//   of benchmarks.md §6.2 (free air and surface burst; those values come from the ConWep/BRL
//   polynomials, Swisdak 1994 and OpenRadioss's tables, which agree among themselves to
//   0.1-2 %: 1 % is the band) and of blastFoam's Swisdak data for 10 kg;
// - Hopkinson-Cranz scaling: at the same Z the pressures are the same and the impulses and
//   times scale as W^(1/3);
// - each Friedlander pulse's impulse is the fit's (to the quadrature's 1e-6, the issue asks
//   0.5 %);
// - the angle of incidence law at 0, 45 and 90 degrees and behind the face.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "fpmshell/loads/blast/blast_load.hpp"
#include "fpmshell/loads/blast/friedlander_pulse.hpp"
#include "fpmshell/loads/blast/kingery_bulmash.hpp"

using namespace fpmshell;

namespace {

// benchmarks.md §6.2: Z, Pso [kPa], Pr [kPa], is, ir [kPa ms/kg^(1/3)], ta, t0 [ms/kg^(1/3)]
struct Row {
    Real z, pso, pr, is, ir, ta, t0;
};
constexpr std::array<Row, 6> k_free_air{{{0.5, 3885, 3.036e4, 141.3, 1454, 0.1541, 0.320},
                                         {1, 934.9, 5006, 174.5, 559.0, 0.5318, 1.795},
                                         {2, 194.7, 645.8, 92.12, 235.7, 1.944, 1.846},
                                         {3, 81.59, 215.5, 64.33, 147.1, 3.987, 2.685},
                                         {5, 31.30, 70.02, 40.62, 83.32, 8.995, 3.333},
                                         {10, 11.09, 23.31, 21.13, 39.71, 22.72, 4.200}}};
constexpr std::array<Row, 6> k_surface{{{0.5, 4888, 3.942e4, 166.2, 2371, 0.1432, 0},
                                        {1, 1354, 8152, 236.3, 884.7, 0.4675, 0},
                                        {2, 283.7, 1058, 134.6, 363.8, 1.693, 0},
                                        {3, 115.7, 330.7, 92.70, 224.3, 3.546, 0},
                                        {5, 43.23, 100.9, 59.31, 125.6, 8.242, 0},
                                        {10, 14.89, 31.54, 31.04, 59.33, 21.66, 0}}};

void expect_within(Real value, Real reference, Real band, const char* what, Real z) {
    EXPECT_LT(std::abs(value / reference - 1.0), band)
        << what << " at Z = " << z << ": " << value << " against " << reference;
}

void check_table(BlastBurst burst, const std::array<Row, 6>& table) {
    for (const Row& r : table) {
        const BlastWave w = kingery_bulmash(burst, 1.0, r.z);  // W = 1 kg: R = Z
        expect_within(w.incident_pressure, 1e3 * r.pso, 0.01, "Pso", r.z);
        expect_within(w.reflected_pressure, 1e3 * r.pr, 0.01, "Pr", r.z);
        expect_within(w.incident_impulse, r.is, 0.01, "is", r.z);  // kPa ms = Pa s
        expect_within(w.reflected_impulse, r.ir, 0.01, "ir", r.z);
        expect_within(w.arrival_time, 1e-3 * r.ta, 0.01, "ta", r.z);
        if (r.t0 > 0) expect_within(w.duration, 1e-3 * r.t0, 0.01, "t0", r.z);
    }
}

/// The pulse's impulse over its positive phase by Simpson's rule on 20 000 intervals.
Real pulse_impulse(Real peak, Real duration, Real decay) {
    const int n = 20000;
    const Real h = duration / n;
    Real sum = 0;
    for (int i = 0; i <= n; ++i) {
        const Real weight = i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += weight * friedlander_pressure(peak, duration, decay, i * h);
    }
    return sum * h / 3.0;
}

}  // namespace

TEST(KingeryBulmash, FreeAirFitsMatchTheTabulatedValues) {
    check_table(BlastBurst::FreeAir, k_free_air);
}

TEST(KingeryBulmash, SurfaceBurstFitsMatchTheTabulatedValues) {
    check_table(BlastBurst::Surface, k_surface);
}

TEST(KingeryBulmash, SurfaceBurstOfTenKilogramsMatchesSwisdaksData) {
    // blastFoam's validation data (Swisdak 1994) for 10 kg of TNT on the ground: R [m], Pso
    // [kPa], is [kPa ms], ta [ms]
    const std::array<std::array<Real, 4>, 4> data{{{1, 5472, 360.3, 0.2744},
                                                   {2, 1585, 497, 0.8809},
                                                   {5, 202.4, 250.6, 4.811},
                                                   {10, 49.27, 136.3, 15.82}}};
    for (const auto& d : data) {
        const BlastWave w = kingery_bulmash(BlastBurst::Surface, 10.0, d[0]);
        expect_within(w.incident_pressure, 1e3 * d[1], 0.01, "Pso", d[0]);
        expect_within(w.incident_impulse, d[2], 0.01, "is", d[0]);
        expect_within(w.arrival_time, 1e-3 * d[3], 0.01, "ta", d[0]);
    }
}

TEST(KingeryBulmash, HopkinsonCranzScaling) {
    for (const BlastBurst burst : {BlastBurst::FreeAir, BlastBurst::Surface})
        for (const Real z : {0.3, 1.0, 4.0, 20.0}) {
            const BlastWave one = kingery_bulmash(burst, 1.0, z);
            const BlastWave eight = kingery_bulmash(burst, 8.0, 2.0 * z);  // W^(1/3) = 2
            EXPECT_NEAR(eight.incident_pressure / one.incident_pressure, 1.0, 1e-12);
            EXPECT_NEAR(eight.reflected_pressure / one.reflected_pressure, 1.0, 1e-12);
            EXPECT_NEAR(eight.incident_impulse / one.incident_impulse, 2.0, 1e-12);
            EXPECT_NEAR(eight.reflected_impulse / one.reflected_impulse, 2.0, 1e-12);
            EXPECT_NEAR(eight.arrival_time / one.arrival_time, 2.0, 1e-12);
            EXPECT_NEAR(eight.duration / one.duration, 2.0, 1e-12);
        }
}

TEST(KingeryBulmash, BeyondTheFitsTheWaveDecaysAsOneOverDistance) {
    // eq. 6.13-2: continuous at Z = 40, then 1/Z and the front at the speed of sound
    const BlastWave at = kingery_bulmash(BlastBurst::FreeAir, 1.0, 40.0);
    const BlastWave far = kingery_bulmash(BlastBurst::FreeAir, 1.0, 80.0);
    EXPECT_NEAR(far.incident_pressure / at.incident_pressure, 0.5, 1e-12);
    EXPECT_NEAR(far.reflected_impulse / at.reflected_impulse, 0.5, 1e-12);
    EXPECT_NEAR(far.arrival_time - at.arrival_time, 40.0 / 340.29, 1e-12);
    EXPECT_EQ(far.duration, at.duration);
    // and nothing but finite positive values from the charge's surface out
    for (const BlastBurst burst : {BlastBurst::FreeAir, BlastBurst::Surface})
        for (Real z = 0.01; z < 100; z *= 1.07) {
            const BlastWave w = kingery_bulmash(burst, 1.0, z);
            for (const Real v : {w.incident_pressure, w.reflected_pressure, w.incident_impulse,
                                 w.reflected_impulse, w.arrival_time, w.duration})
                EXPECT_TRUE(std::isfinite(v) && v > 0) << "Z = " << z;
            EXPECT_GT(w.reflected_pressure, w.incident_pressure) << "Z = " << z;
        }
}

TEST(FriedlanderPulse, ImpulseIsTheFits) {
    for (const BlastBurst burst : {BlastBurst::FreeAir, BlastBurst::Surface})
        for (Real z = 0.06; z < 45; z *= 1.1) {
            const BlastWave w = kingery_bulmash(burst, 1.0, z);
            for (const bool reflected : {false, true}) {
                const Real peak = reflected ? w.reflected_pressure : w.incident_pressure;
                const Real impulse = reflected ? w.reflected_impulse : w.incident_impulse;
                const Real b = friedlander_decay(peak, w.duration, impulse);
                EXPECT_NEAR(pulse_impulse(peak, w.duration, b) / impulse, 1.0, 1e-6)
                    << "Z = " << z << (reflected ? " reflected" : " incident");
            }
        }
    // the incident decays of the free-air burst by the independent bisection of
    // tools/theory_checks/test_blast.py (to its 6 printed decimals)
    const std::array<std::array<Real, 2>, 5> decays{
        {{0.5, 7.638969}, {1, 8.480013}, {2, 2.442618}, {5, 0.801864}, {10, 0.299021}}};
    for (const auto& [z, b] : decays) {
        const BlastWave w = kingery_bulmash(BlastBurst::FreeAir, 1.0, z);
        EXPECT_NEAR(friedlander_decay(w.incident_pressure, w.duration, w.incident_impulse), b, 1e-6)
            << "Z = " << z;
    }
    // the triangle (b = 0) and a decay known in closed form
    EXPECT_NEAR(friedlander_decay(2.0, 3.0, 3.0), 0.0, 1e-12);
    EXPECT_NEAR(friedlander_decay(1.0, 1.0, friedlander_impulse_ratio(2.5)), 2.5, 1e-12);
    EXPECT_NEAR(friedlander_impulse_ratio(1e-4), friedlander_impulse_ratio(1.0001e-3), 2e-4);
}

TEST(FriedlanderPulse, NegativePhaseContinuesTheCurve) {
    // eq. 6.13-5: past t0 the curve goes on below zero; its impulse there is -P t0 e^-b / b^2
    // (Simpson's rule over 60 t0, where e^-60b has left no digit of it); a pulse of b <= 0 has
    // none (its continuation would grow without bound); off, nothing past t0
    const Real peak = 7.0e4, t0 = 3.3e-3;
    for (const Real b : {0.8, 2.5}) {
        const int n = 60000;
        const Real h = 60.0 * t0 / n;
        Real sum = 0;
        for (int i = 0; i <= n; ++i) {
            const Real weight = i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0);
            sum += weight * friedlander_pressure(peak, t0, b, t0 + i * h, true);
        }
        EXPECT_NEAR(sum * h / 3.0 / friedlander_negative_impulse(peak, t0, b), 1.0, 1e-9) << b;
        EXPECT_LT(friedlander_pressure(peak, t0, b, 1.5 * t0, true), 0.0);
        EXPECT_EQ(friedlander_pressure(peak, t0, b, 1.5 * t0, false), 0.0);
    }
    EXPECT_EQ(friedlander_pressure(peak, t0, -0.1, 1.5 * t0, true), 0.0);
    EXPECT_GT(friedlander_pressure(peak, t0, -0.1, 0.5 * t0, true), 0.0);
}

TEST(BlastIncidence, AngleLawAtZeroFortyFiveNinetyAndBehind) {
    const Real pso = 100, pr = 450;
    EXPECT_DOUBLE_EQ(blast_incidence_pressure(pso, pr, 1.0), pr);  // head on: reflected
    const Real c = std::sqrt(0.5);  // 45 degrees: Pr / 2 + Pso (1 + c - 1)
    EXPECT_NEAR(blast_incidence_pressure(pso, pr, c), 0.5 * pr + c * pso, 1e-12);
    EXPECT_DOUBLE_EQ(blast_incidence_pressure(pso, pr, 0.0), pso);   // grazing: side-on
    EXPECT_DOUBLE_EQ(blast_incidence_pressure(pso, pr, -0.6), pso);  // behind: side-on
    // continuous where the face turns away
    EXPECT_NEAR(blast_incidence_pressure(pso, pr, 1e-9), pso, 1e-6);
}
