// The reductions of history requests over their node sets (model-format.md "output"):
// mass_mean is the set's momentum over its mass, which a free body keeps while it vibrates;
// the pressure gauge reads a uniform pressure on a curved shell at every particle.
#include <gtest/gtest.h>

#include <cmath>

#include "../one_section_model.hpp"
#include "../run_to.hpp"
#include "fpmshell/driver/history_sampler.hpp"

namespace fpmshell {
namespace {

/// A free plate of unequal particle masses (corners, edges, inside), each particle started with
/// its own velocity, and two histories of vx over all particles: mean and mass_mean.
Model uneven_free_plate() {
    PlateParams pp;
    pp.nx = pp.ny = 4;
    pp.pattern = DiagonalPattern::Alternate;
    Model m = test::one_section_model(generate_plate(pp), 0.01);
    for (Index p = 0; p < m.n_particles(); ++p)
        m.initial_conditions.push_back(
            {{p},
             Vec3(static_cast<Real>(p % 7), 0, 0.01 * static_cast<Real>(p % 3)),
             Vec3::Zero()});
    m.control.end_time = 1;
    for (const Reduce r : {Reduce::Mean, Reduce::MassMean}) {
        HistoryRequest h;
        h.name = r == Reduce::Mean ? "vx_mean" : "vx_mass_mean";
        for (Index p = 0; p < m.n_particles(); ++p) h.nodes.push_back(p);
        h.quantity = Quantity::Vx;
        h.reduce = r;
        m.output.histories.push_back(h);
    }
    return m;
}

TEST(HistorySampler, MassMeanIsTheMomentumOverTheMass) {
    const Model m = uneven_free_plate();
    const ExplicitSolver s(m);
    Real momentum = 0, mass = 0, plain = 0;
    for (Index p = 0; p < m.n_particles(); ++p) {
        const Real mp = s.state().mass[static_cast<std::size_t>(p)];
        momentum += mp * static_cast<Real>(p % 7);
        mass += mp;
        plain += static_cast<Real>(p % 7);
    }
    const std::vector<Real> v = sample_histories(m, s);
    EXPECT_NEAR(v[0], plain / static_cast<Real>(m.n_particles()), 1e-12);
    EXPECT_NEAR(v[1], momentum / mass, 1e-12);
    // the masses are uneven, so the two differ: the test tells one from the other
    EXPECT_GT(std::abs(v[1] - v[0]), 0.05);
}

TEST(HistorySampler, AFreeBodysMassMeanVelocityStaysWhileItsParticlesVibrate) {
    const Model m = uneven_free_plate();
    ExplicitSolver s(m);
    const std::vector<Real> start = sample_histories(m, s);
    test::run_to(s, 200 * s.stable_dt());
    const std::vector<Real> later = sample_histories(m, s);
    // no external force: the momentum is kept to rounding (relative 1e-12 of the speeds of ~6)
    EXPECT_NEAR(later[1], start[1], 1e-11);
    // while the particles' plain mean moves with the vibration
    EXPECT_GT(std::abs(later[0] - start[0]), 1e-3);
}

}  // namespace
TEST(HistorySampler, ThePressureGaugeReadsAUniformPressureOnACurvedShell) {
    SphericalCapParams cp;
    cp.radius = 2.0;
    cp.half_angle_deg = 30;
    cp.divisions = 6;
    Model m = test::one_section_model(generate_spherical_cap(cp), 0.01);
    Load p;
    p.type = LoadType::Pressure;
    for (Index e = 0; e < static_cast<Index>(m.triangles.size()); ++e) p.elements.push_back(e);
    p.pressure = 3.5e5;
    m.loads.push_back(p);
    ExplicitSolver s(m);
    s.step(1e30);
    for (Index q = 0; q < m.n_particles(); ++q)  // rim, inside, apex: each its own fan
        EXPECT_NEAR(particle_quantity(s, Quantity::Pressure, q) / p.pressure, 1.0, 1e-12) << q;
}

}  // namespace fpmshell
