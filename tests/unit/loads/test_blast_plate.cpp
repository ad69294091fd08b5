// The air blast on a model (solver/external_loads.cpp, theory.md §6.13): a small free steel
// plate 1 m from 1 kg of TNT, facing the charge, takes the momentum of the reflected impulse
// times its area (the 2 %), and to 1 % the sum over its faces of each face's impulse
// by the angle law (what remains is the step's sampling of a pulse that starts with a jump:
// about dt / t0); no force before the shock arrives nor after its positive phase; the energy
// balance closes; a plate whose normal turns away from the charge takes the side-on impulse
// pushing it toward the charge.
#include <gtest/gtest.h>

#include <cmath>

#include "eroding_band.hpp"
#include "fpmshell/loads/blast/blast_load.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "one_section_model.hpp"
#include "run_to.hpp"

using namespace fpmshell;

namespace {

constexpr Real k_side = 0.1, k_thickness = 0.005, k_standoff = 1.0;

Model blast_plate(bool facing, Real standoff = k_standoff) {
    PlateParams pp;
    pp.length_x = pp.length_y = k_side;
    pp.nx = pp.ny = 4;
    Model m = test::one_section_model(generate_plate(pp), k_thickness);
    BlastLoad b;
    for (Index e = 0; e < static_cast<Index>(m.triangles.size()); ++e) b.elements.push_back(e);
    b.charge_mass = 1.0;
    b.centre = Vec3(0.5 * k_side, 0.5 * k_side, facing ? standoff : -standoff);
    m.blast_loads.push_back(b);
    return m;
}

Vec3 momentum(const ExplicitSolver& s) {
    Vec3 p = Vec3::Zero();
    for (std::size_t i = 0; i < s.state().size(); ++i) p += s.state().mass[i] * s.state().v[i];
    return p;
}

/// sum over the faces of A [ir cos^2 + is (1 + cos - 2 cos^2)] (the angle law's impulse), or
/// of A is where the face does not see the charge; with `negative`, of the impulses of the
/// pulses' negative phases (eq. 6.13-5) instead
Real face_impulses(const Model& m, bool negative = false) {
    const BlastLoad& b = m.blast_loads[0];
    Real sum = 0;
    for (const auto& t : m.triangles) {
        const Vec3 &a = m.nodes[static_cast<std::size_t>(t[0])],
                   &c1 = m.nodes[static_cast<std::size_t>(t[1])],
                   &c2 = m.nodes[static_cast<std::size_t>(t[2])];
        const Vec3 cross = (c1 - a).cross(c2 - a), centroid = (a + c1 + c2) / 3.0;
        const Vec3 to_charge = b.centre - centroid;
        const Real c = cross.dot(to_charge) / (cross.norm() * to_charge.norm());
        BlastWave w = kingery_bulmash(b.burst, b.charge_mass, to_charge.norm());
        if (negative) {
            const Real b_i = friedlander_decay(w.incident_pressure, w.duration, w.incident_impulse);
            const Real b_r =
                friedlander_decay(w.reflected_pressure, w.duration, w.reflected_impulse);
            w.incident_impulse = friedlander_negative_impulse(w.incident_pressure, w.duration, b_i);
            w.reflected_impulse =
                friedlander_negative_impulse(w.reflected_pressure, w.duration, b_r);
        }
        const Real impulse =
            c > 0 ? w.reflected_impulse * c * c + w.incident_impulse * (1 + c - 2 * c * c)
                  : w.incident_impulse;
        sum += 0.5 * cross.norm() * impulse;
    }
    return sum;
}

}  // namespace

TEST(BlastPlate, FreePlateTakesTheReflectedImpulse) {
    const Model m = blast_plate(true);
    const BlastWave head_on = kingery_bulmash(BlastBurst::FreeAir, 1.0, k_standoff);
    ExplicitSolver s(m);
    // nothing before the nearest face's arrival
    test::run_to(s, 0.95 * head_on.arrival_time);
    EXPECT_LT(momentum(s).norm(), 1e-20);  // (rounding of the unloaded plate's forces)
    // after the furthest face's positive phase
    const Real far = std::hypot(k_standoff, std::sqrt(0.5) * k_side);
    const BlastWave last = kingery_bulmash(BlastBurst::FreeAir, 1.0, far);
    test::run_to(s, last.arrival_time + last.duration);
    const Vec3 p_end = momentum(s);
    const Real area = k_side * k_side;
    EXPECT_NEAR(-p_end.z() / (head_on.reflected_impulse * area), 1.0, 0.02);
    EXPECT_NEAR(-p_end.z() / face_impulses(m), 1.0, 0.01);
    EXPECT_NEAR(p_end.x() / p_end.z(), 0.0, 1e-9);  // the charge over the plate's centre
    // the pulse is over: no more momentum
    test::run_to(s, s.time() + 0.3e-3);
    EXPECT_NEAR((momentum(s) - p_end).norm() / p_end.norm(), 0.0, 1e-12);
    EXPECT_LT(std::abs(s.energy().error()), 1e-3);
}

TEST(BlastPlate, FaceTurnedAwayTakesTheSideOnImpulseTowardTheCharge) {
    // the charge below the plate, whose normal points up (away from it): the face does not see
    // the charge, so it takes the side-on pressure, pushing against its normal (toward -z, the
    // charge): LS-DYNA's convention, where a segment's normal must point to the charge
    const Model m = blast_plate(false);
    ExplicitSolver s(m);
    const Real far = std::hypot(k_standoff, std::sqrt(0.5) * k_side);
    const BlastWave last = kingery_bulmash(BlastBurst::FreeAir, 1.0, far);
    test::run_to(s, last.arrival_time + last.duration);
    EXPECT_NEAR(-momentum(s).z() / face_impulses(m), 1.0, 0.01);
    const BlastWave head_on = kingery_bulmash(BlastBurst::FreeAir, 1.0, k_standoff);
    EXPECT_NEAR(-momentum(s).z() / (head_on.incident_impulse * k_side * k_side), 1.0, 0.02);
}

TEST(BlastPlate, NegativePhaseTakesBackTheContinuedCurvesImpulse) {
    // eq. 6.13-5 at Z = 5 (1 kg at 5 m: decays near 1, a suction a tenth of the peak, far from
    // the floor): after the positive phase the plate has the angle law's impulse; 30 positive
    // phases later (e^-30b: the tail is spent) the negative phases' impulse has come back off
    // it, to 1 % (the step's sampling, as the positive phase's); the balance closes
    constexpr Real standoff = 5.0;
    Model m = blast_plate(true, standoff);
    m.blast_loads[0].negative_phase = true;
    ExplicitSolver s(m);
    const Real far = std::hypot(standoff, std::sqrt(0.5) * k_side);
    const BlastWave last = kingery_bulmash(BlastBurst::FreeAir, 1.0, far);
    test::run_to(s, last.arrival_time + last.duration);
    const Real positive = -momentum(s).z();
    EXPECT_NEAR(positive / face_impulses(m), 1.0, 0.01);
    test::run_to(s, last.arrival_time + 30 * last.duration);
    const Real negative = -momentum(s).z() - positive;
    const Real expected = face_impulses(m, true);
    EXPECT_LT(expected, -0.5 * positive);  // a suction that matters (0.75 of the positive)
    EXPECT_NEAR(negative / expected, 1.0, 0.01);
    EXPECT_LT(std::abs(s.energy().error()), 1e-3);
}

TEST(BlastPlate, SuctionStopsAtTheVacuum) {
    // 1 kg of TNT 10 m behind a face (normal +z, away from it: the side-on pulse, decay 0.30),
    // its pressure scaled 100 times: the continued curve's deepest point, at tau = t0 (1 + 1/b),
    // would be -1 MPa; the pressure stops at -p_ambient (model units m, t, s: kPa), and
    // without the negative phase there is none
    BlastLoad b;
    b.elements = {0};
    b.charge_mass = 1.0e-3;  // t
    b.centre = Vec3(0, 0, -10.0);
    b.kilograms = 1e3;
    b.scale = 100;
    const std::vector<Vec3> nodes{{-0.01, -0.01, 0}, {0.01, -0.01, 0}, {0, 0.01, 0}};
    const std::vector<std::array<Index, 3>> tri{{0, 1, 2}};
    b.negative_phase = true;
    const BlastFaces with(b, nodes, tri);
    b.negative_phase = false;
    const BlastFaces without(b, nodes, tri);
    const BlastWave w = kingery_bulmash(BlastBurst::FreeAir, 1.0, 10.0);
    const Real decay = friedlander_decay(w.incident_pressure, w.duration, w.incident_impulse);
    const Real deepest = with.arrival(0) + (1.0 + 1.0 / decay) * with.duration(0);
    ASSERT_LT(100 * friedlander_pressure(w.incident_pressure, w.duration, decay,
                                         (1.0 + 1.0 / decay) * w.duration, true),
              -5 * BlastFaces::k_ambient_pressure);
    EXPECT_EQ(with.pressure(0, deepest, -1.0), -101.325);
    EXPECT_EQ(without.pressure(0, deepest, -1.0), 0.0);
    const RealPack packed = with.pressures(0, deepest, RealPack(-1.0));
    EXPECT_EQ(lane(packed, 0), -101.325);
    for (int l = 1; l < k_lanes; ++l) EXPECT_EQ(lane(packed, l), 0.0);  // padding
    // the scalar and the pack agree along the pulse, in and past its positive phase
    for (const Real tau : {0.2, 0.9, 1.1, 3.0, 12.0, 40.0}) {
        const Real t = with.arrival(0) + tau * with.duration(0);
        EXPECT_NEAR(lane(with.pressures(0, t, RealPack(0.3)), 0), with.pressure(0, t, 0.3),
                    1e-12 * 101.325)
            << tau;
        if (tau > 1) {
            EXPECT_LT(with.pressure(0, t, 0.3), 0.0) << tau;
        }
    }
}

TEST(BlastPlate, ModelUnitsConvertTheWave) {
    // the plate of FreePlateTakesTheReflectedImpulse in mm, kg and ms (LS-DYNA's UNIT 6, whose
    // pressure unit kg/(mm ms^2) is the GPa): the same pulse, in those units
    const Model si = blast_plate(true);
    BlastLoad mm = si.blast_loads[0];
    std::vector<Vec3> nodes_mm = si.nodes;
    for (Vec3& x : nodes_mm) x *= 1e3;
    mm.centre *= 1e3;
    mm.charge_mass = 1.0;  // kg, the mass unit
    mm.metres = 1e-3;
    mm.kilograms = 1.0;
    mm.seconds = 1e-3;
    const BlastFaces in_si(si.blast_loads[0], si.nodes, si.triangles);
    const BlastFaces in_mm(mm, nodes_mm, si.triangles);
    for (std::size_t k = 0; k < in_si.size(); ++k) {
        EXPECT_NEAR(in_mm.arrival(k) * 1e-3 / in_si.arrival(k), 1.0, 1e-12);
        for (const Real tau : {0.1, 0.5, 0.9}) {
            const Real t = in_si.arrival(k) + tau * in_si.duration(k);
            EXPECT_NEAR(in_mm.pressure(k, t * 1e3, 0.8) * 1e9 / in_si.pressure(k, t, 0.8), 1.0,
                        1e-9);
        }
    }
}

TEST(BlastPlate, ADampedPlateStruckAtRestKeepsItsBalance) {
    // theory.md eq. 6.8-4: with mass damping, the cycle in which the shock strikes the plate at
    // rest books no damping ahead of the kinetic energy; every step's balance closes to 1e-3
    // once the plate moves (before, its energies are rounding: no ratio to check), and the
    // damped plate takes less momentum than the free one
    Model m = blast_plate(true);
    m.damping.mass = 50;
    ExplicitSolver s(m);
    const Real far = std::hypot(k_standoff, std::sqrt(0.5) * k_side);
    const BlastWave last = kingery_bulmash(BlastBurst::FreeAir, 1.0, far);
    Real worst = 0;
    while (s.time() < last.arrival_time + last.duration) {
        s.step(1e30);
        if (s.energy().kinetic > 1e-6) worst = std::max(worst, std::abs(s.energy().error()));
    }
    EXPECT_LT(worst, 1e-3);
    EXPECT_GT(s.energy().dissipated_by_damping(), 0);
}

TEST(BlastPlate, ABlastOnARigidPartMovesThePart) {
    // half the plate a rigid part (theory.md §6.11): the blast's forces on its particles move
    // it as one body; the whole plate still takes the angle law's impulse
    Model m = blast_plate(true);
    m.materials.push_back({"hard", "rigid", 7800, 2.1e11, 0.3});
    m.sections.push_back({1, k_thickness, 2, 3});
    for (std::size_t e = 0; e < m.triangles.size() / 2; ++e) m.element_section[e] = 1;
    ExplicitSolver s(m);
    const Real far = std::hypot(k_standoff, std::sqrt(0.5) * k_side);
    const BlastWave last = kingery_bulmash(BlastBurst::FreeAir, 1.0, far);
    test::run_to(s, last.arrival_time + last.duration);
    EXPECT_NEAR(-momentum(s).z() / face_impulses(m), 1.0, 0.01);
    // the rigid half's particles: all moving, at velocities of one rigid motion (equal z
    // velocity where it does not turn: compare their spread with their mean)
    Real lo = 1e30, hi = -1e30;
    for (std::size_t e = 0; e < m.triangles.size() / 2; ++e)
        for (const Index p : m.triangles[e]) {
            lo = std::min(lo, s.state().v[static_cast<std::size_t>(p)].z());
            hi = std::max(hi, s.state().v[static_cast<std::size_t>(p)].z());
        }
    EXPECT_LT(hi, -1.0);  // pushed away from the charge, m/s
    EXPECT_LT(hi - lo, 0.2 * std::abs(hi));
}

TEST(BlastPlate, PressuresAndBlastsOnErodedFacesStop) {
    // the band of the torn plate (eroding_band.hpp) under a uniform pressure and a blast
    // passing through the erosion: once every face around a particle has eroded it takes no
    // load from them (LS-DYNA drops the segment loads of deleted elements); the others still do
    Model m = test::eroding_band_plate(20);
    Load p;
    p.type = LoadType::Pressure;
    for (Index e = 0; e < static_cast<Index>(m.triangles.size()); ++e) p.elements.push_back(e);
    p.pressure = 1.0e4;
    m.loads.push_back(p);
    BlastLoad b;
    b.elements = p.elements;
    b.charge_mass = 1.0;
    b.centre = Vec3(0.5, 0.5, 2.0);
    b.detonation_time = 1.0e-3;  // its phase spans the erosion (from about 1.3 ms)
    m.blast_loads.push_back(b);
    ExplicitSolver s(m);
    test::run_to(s, m.control.end_time);
    ASSERT_GT(s.eroded_elements(), 0);
    int free = 0, loaded = 0;
    for (Index q = 0; q < m.n_particles(); ++q) {
        bool any_live = false;
        for (const Index e : s.topology().elements_of(q))
            any_live = any_live || !s.elements().eroded(e);
        const Real f = s.state().f_ext[static_cast<std::size_t>(q)].norm();
        if (any_live) {
            loaded += f > 0;
        } else {
            ++free;
            EXPECT_EQ(f, 0.0) << "particle " << q;
        }
    }
    EXPECT_GT(free, 0);
    EXPECT_EQ(loaded, m.n_particles() - free);
}
