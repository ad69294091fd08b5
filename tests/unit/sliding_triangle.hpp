// A flat triangle resting on a rigid plane and pressed onto it by its weight, for the tests of
// friction (contact/test_contact_friction.cpp) and of the energy balance of a model that does
// not move (solver/test_energy_balance.cpp).
#pragma once

#include <vector>

#include "fpmshell/solver/explicit_solver.hpp"
#include "one_section_model.hpp"

namespace fpmshell::test {

constexpr Real k_h = 0.01;  // thickness: the triangle's mid-surface rests h/2 above the plane
constexpr Real k_g = 100;   // the pressing acceleration

struct Sliding {
    Real friction = 0.3;
    Vec3 velocity = Vec3::Zero();  ///< of the triangle at t = 0
    Real push = 0;                 ///< force along x per node, times m_i g
    Vec3 body_velocity = Vec3::Zero();
    Real body_mass = 0;  ///< 0: a fixed plane
    Real lift = 0;       ///< initial gap to the plane (0: resting on it)
    ContactMethod method = ContactMethod::LagrangeMultiplier;
};

/// A flat triangle (legs 1 m) on the plane z = 0 (normal +z), pressed by m_i g per node, its
/// mid-surface h/2 + lift above the plane.
inline Model sliding_triangle(const Sliding& c) {
    MeshData mesh;
    const Real z = 0.5 * k_h + c.lift;
    mesh.nodes = {Vec3(0, 0, z), Vec3(1, 0, z), Vec3(0, 1, z)};
    mesh.triangles = {{0, 1, 2}};
    Model m = test::one_section_model(mesh, k_h);
    m.control.end_time = 1;
    const std::vector<Index> all{0, 1, 2};
    m.initial_conditions.push_back({all, c.velocity, Vec3::Zero()});
    const std::vector<Real> mass = ExplicitSolver(m).state().mass;
    for (Index p : all)
        m.loads.push_back({LoadType::Force,
                           {p},
                           {},
                           0,
                           mass[static_cast<std::size_t>(p)] * k_g * Vec3(c.push, 0, -1),
                           -1});
    RigidBody plane;
    plane.name = "plane";
    plane.normal = Vec3::UnitZ();
    plane.velocity = c.body_velocity;
    plane.fixed = c.body_mass == 0;
    plane.mass = c.body_mass;
    m.rigid_bodies.push_back(plane);
    ContactDefinition contact;
    contact.type = ContactType::Rigid;
    contact.body = 0;
    contact.nodes = all;
    contact.friction = c.friction;
    contact.method = c.method;
    m.contacts.push_back(contact);
    return m;
}

}  // namespace fpmshell::test
