// Coulomb friction in the shell self-contact (theory.md §8.4): a flat triangle (legs 1 m) resting
// on a shell sheet of the same model, pressed onto it by forces m_i g (a weight), the particles
// of the triangle against the faces of the sheet:
// - on a held sheet, sliding at v0 it decelerates at mu g, stops at t = v0 / (mu g) after
//   v0^2 / (2 mu g) and stays; the friction's work is its kinetic energy;
// - with LS-DYNA's decay mu = FD + (FS - FD) exp(-DC v) (eq. 8.4-5) it stops at the closed form
//   t = ln((FD e^(DC v0) + FS - FD) / FS) / (g FD DC);
// - on a free sheet the friction exchanges momentum between the two: the total along the sheet
//   is conserved and their sliding stops.
// (The same bytes on 1 and 2 threads with friction: ContactSweeps.* of test_contact_parallel.cpp.)
#include <gtest/gtest.h>

#include <cmath>

#include "fpmshell/solver/explicit_solver.hpp"
#include "one_section_model.hpp"
#include "run_to.hpp"

using namespace fpmshell;
using test::run_to;

namespace {

constexpr Real k_h = 0.01;  // thickness of both: the triangle's mid-surface rests h above the sheet
constexpr Real k_g = 100;   // the pressing acceleration

struct SlidingOnSheet {
    Real fs = 0.3, fd = 0, dc = 0;  // FS, FD, DC (dc 0: mu = fs)
    Real v0 = 1;
    bool sheet_held = true;  // else free, pressed up below the triangle by its weight
    ContactMethod method = ContactMethod::LagrangeMultiplier;
};

constexpr std::array<Index, 3> k_slider{4, 5, 6};

/// Sheet: nodes 0-3, the square [-1, 3]^2 in z = 0, two triangles; slider: nodes 4-6 at z = h,
/// legs 1 m, its centroid above the sheet's centre (1, 1).
Model sliding_on_sheet(const SlidingOnSheet& c) {
    MeshData mesh;
    mesh.nodes = {Vec3(-1, -1, 0),        Vec3(3, -1, 0),          Vec3(3, 3, 0),
                  Vec3(-1, 3, 0),         Vec3(2, 2, 3 * k_h) / 3, Vec3(5, 2, 3 * k_h) / 3,
                  Vec3(2, 5, 3 * k_h) / 3};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}};
    Model m = test::one_section_model(mesh, k_h);
    m.control.end_time = 1;
    const std::vector<Index> slider(k_slider.begin(), k_slider.end()), sheet{0, 1, 2, 3};
    m.initial_conditions.push_back({slider, Vec3(c.v0, 0, 0), Vec3::Zero()});
    const std::vector<Real> mass = ExplicitSolver(m).state().mass;
    for (Index p : slider)
        m.loads.push_back({LoadType::Force,
                           {p},
                           {},
                           0,
                           mass[static_cast<std::size_t>(p)] * k_g * Vec3(0, 0, -1),
                           -1});
    if (c.sheet_held) {
        BoundaryCondition held;
        held.nodes = sheet;
        held.fixed = {true, true, true, true, true, true};
        m.boundary.push_back(held);
    } else {
        // the triangle's weight back up on the sheet's four corners, a quarter each: no net
        // force and no torque on the pair (the triangle's centroid is above the sheet's centre)
        Real weight = 0;
        for (Index p : slider) weight += mass[static_cast<std::size_t>(p)] * k_g;
        for (Index p : sheet)
            m.loads.push_back({LoadType::Force, {p}, {}, 0, 0.25 * weight * Vec3(0, 0, 1), -1});
    }
    ContactDefinition contact;
    contact.type = ContactType::Self;
    contact.elements = {0, 1, 2};
    contact.exclusion_radius = 0.1 * k_h;  // the triangle starts touching the sheet: not excluded
    contact.friction = c.fs;
    contact.friction_dynamic = c.fd;
    contact.friction_decay = c.dc;
    contact.method = c.method;
    m.contacts.push_back(contact);
    return m;
}

Real slider_mass(const ExplicitSolver& s) {
    Real m = 0;
    for (Index p : k_slider) m += s.state().mass[static_cast<std::size_t>(p)];
    return m;
}

/// The time at which the slider's velocity along x first falls to 0 (to a step).
Real stop_time(ExplicitSolver& s, Real limit) {
    while (s.time() < limit) {
        s.step(1e30);
        if (s.state().v[static_cast<std::size_t>(k_slider[0])].x() <= 1e-12) return s.time();
    }
    return limit;
}

}  // namespace

TEST(ContactSelfFriction, ATriangleSlidingOnAHeldSheetStopsAfterTheCoulombDistance) {
    const SlidingOnSheet c;
    const Model m = sliding_on_sheet(c);
    ExplicitSolver s(m);
    const Real mu = c.fs, t_stop = c.v0 / (mu * k_g), distance = c.v0 * c.v0 / (2 * mu * k_g);
    const Real dt = run_to(s, 0.5 * t_stop);
    for (Index p : k_slider)  // v = v0 - mu g t at the half step; one step's deceleration
        EXPECT_NEAR(s.state().v[static_cast<std::size_t>(p)].x(),
                    c.v0 - mu * k_g * (s.time() - 0.5 * dt), mu * k_g * dt);
    // the push on the slider: its weight up and the friction back (RCFORC's slave side)
    const Real weight = slider_mass(s) * k_g;
    EXPECT_NEAR(s.contact_force(0).z(), weight, 1e-6 * weight);
    EXPECT_NEAR(s.contact_force(0).x(), -mu * weight, 1e-6 * weight);
    run_to(s, 2 * t_stop);
    for (Index p : k_slider) {
        const auto up = static_cast<std::size_t>(p);
        EXPECT_NEAR(s.state().v[up].x(), 0.0, 1e-9 * c.v0);  // held by the static friction
        EXPECT_NEAR(s.state().x[up].x() - m.nodes[up].x(), distance, c.v0 * dt);
        EXPECT_NEAR(s.state().x[up].z(), k_h, 1e-3 * k_h);  // on the sheet
    }
    // the kinetic energy went into the contact (friction), from t_0 on (eq. 6.8-3); the balance
    // closes to rounding and the trapezoid's O(dt^2) (1e-11 measured)
    const Real kinetic0 = 0.5 * slider_mass(s) * c.v0 * c.v0;
    EXPECT_NEAR(s.energy().contact, kinetic0, 1e-3 * kinetic0);
    EXPECT_LT(std::abs(s.energy().error()), 1e-9);
}

TEST(ContactSelfFriction, TheStaticToDynamicDecayStopsItAtTheClosedFormTime) {
    const SlidingOnSheet c{0.4, 0.2, 2.0, 1.0, true};
    const Model m = sliding_on_sheet(c);
    ExplicitSolver s(m);
    // dv/dt = -g (FD + (FS - FD) e^(-DC v)): t = ln((FD e^(DC v0) + FS - FD) / FS) / (g FD DC)
    const Real t_closed =
        std::log((c.fd * std::exp(c.dc * c.v0) + c.fs - c.fd) / c.fs) / (k_g * c.fd * c.dc);
    const Real t_constant_fs = c.v0 / (c.fs * k_g), t_constant_fd = c.v0 / (c.fd * k_g);
    ASSERT_GT(t_closed, 1.2 * t_constant_fs);  // the decay matters: between the two constants
    ASSERT_LT(t_closed, 0.8 * t_constant_fd);
    const Real t = stop_time(s, 2 * t_constant_fd);
    // the coefficient follows the predictor's sliding speed, a step behind: a few steps
    const Real before = s.time();
    s.step(1e30);
    const Real dt = s.time() - before;
    EXPECT_NEAR(t, t_closed, 3 * dt);
    EXPECT_LT(std::abs(s.energy().error()), 1e-9);
}

TEST(ContactSelfFriction, OnAFreeSheetTheMomentumAlongItIsConservedAndTheSlidingStops) {
    SlidingOnSheet c;
    c.sheet_held = false;
    const Model m = sliding_on_sheet(c);
    ExplicitSolver s(m);
    Real sheet_mass = 0;
    for (std::size_t i = 0; i < 4; ++i) sheet_mass += s.state().mass[i];
    const Real mt = slider_mass(s), p0 = mt * c.v0;
    auto momentum_x = [&] {
        Real p = 0;
        for (std::size_t i = 0; i < m.nodes.size(); ++i)
            p += s.state().mass[i] * s.state().v[i].x();
        return p;
    };
    // the normal force is the triangle's weight m_t g: the relative sliding slows at
    // mu g (1 + m_t / m_s) and stops at v0 / (mu g (1 + m_t / m_s)), at the common velocity
    const Real t_stop = c.v0 / (c.fs * k_g * (1 + mt / sheet_mass));
    // friction is internal to the pair; the velocities change by position differences of
    // contact (x ~ 3 m) over the step: rounding of eps |x| / dt per particle and step
    Real total_mass = 0;
    for (Real mi : s.state().mass) total_mass += mi;
    long steps = 0;
    Real dt = 0;
    auto rounding = [&] { return steps * total_mass * 4 * 3.0 * 2.2e-16 / dt; };
    while (s.time() < 0.5 * t_stop) {
        const Real before = s.time();
        s.step(1e30);
        dt = s.time() - before;
        ++steps;
    }
    EXPECT_NEAR(momentum_x(), p0, rounding());
    EXPECT_GT(s.state().v[0].x(), 0.0);  // the sheet is dragged along
    while (s.time() < 3 * t_stop) {
        s.step(1e30);
        ++steps;
    }
    EXPECT_NEAR(momentum_x(), p0, rounding());
    EXPECT_LT(rounding(), 1e-4 * p0);  // the bound means something
    // the triangle rides on the sheet at the common velocity, the sheet's centre of mass too
    // (its corners ring in-plane, 2e-3 of v0, after the friction's sudden pull: 1e-3 for the
    // triangle, whose contact points lie inside the sheet)
    const Real common = p0 / (mt + sheet_mass);
    for (Index p : k_slider)
        EXPECT_NEAR(s.state().v[static_cast<std::size_t>(p)].x(), common, 1e-3 * c.v0);
    Real sheet_p = 0;
    for (std::size_t i = 0; i < 4; ++i) sheet_p += s.state().mass[i] * s.state().v[i].x();
    EXPECT_NEAR(sheet_p / sheet_mass, common, 1e-3 * c.v0);
    EXPECT_LT(std::abs(s.energy().error()), 1e-8);  // the sheet's ringing aside: 1e-10 measured
}

TEST(ContactSelfFriction, ThePenaltyContactsFrictionOnAFreeSheetKeepsTheMomentum) {
    // the penalty contact's friction (eq. 8.4-6) between a triangle and a free sheet: internal
    // to the pair, it keeps their momentum along the sheet (to rounding: the forces on the
    // slave and on the face's corners are equal and opposite) and drags the sheet along
    SlidingOnSheet c;
    c.sheet_held = false;
    c.method = ContactMethod::Penalty;
    const Model m = sliding_on_sheet(c);
    ExplicitSolver s(m);
    const Real p0 = slider_mass(s) * c.v0;
    run_to(s, 0.02);
    Real p = 0;
    for (std::size_t i = 0; i < m.nodes.size(); ++i) p += s.state().mass[i] * s.state().v[i].x();
    EXPECT_NEAR(p, p0, 1e-9 * p0);
    EXPECT_GT(s.state().v[0].x(), 0.0);  // the sheet moves with the slider
    EXPECT_LT(s.state().v[static_cast<std::size_t>(k_slider[0])].x(), c.v0);  // the slider slows
}
