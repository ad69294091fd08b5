// External loads (solver/external_loads.hpp, theory.md §6.7) and the tangent-plane normals of
// the same pass (§1.3), on a unit square of two triangles in the plane z = 0:
// - a follower pressure p gives the total force -p A n, a third of each triangle's share at
//   its corners; it follows the surface when the square is turned;
// - nodal forces and moments are the value times the curve factor at t;
// - the previous loads move to f_ext_prev (the work of the step needs both).
#include <gtest/gtest.h>

#include "fpmshell/core/rotation.hpp"
#include "fpmshell/solver/external_loads.hpp"

using namespace fpmshell;

namespace {

struct Square {
    Model model;
    Square() {
        model.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
        model.triangles = {{0, 1, 3}, {0, 3, 2}};
        model.materials.push_back({"steel", "elastic", 7800, 2.1e11, 0.3});
        model.sections.push_back({0, 0.01, 2, 3});
        model.element_section.assign(2, 0);
        model.curves.push_back({"ramp", {{0.0, 0.0}, {2.0, 2.0}}});
    }
};

ParticleState state_of(const Model& m) {
    ParticleState s;
    s.resize(m.nodes.size());
    s.x0 = s.x = m.nodes;
    return s;
}

}  // namespace

TEST(ExternalLoads, FollowerPressureAndNodalLoads) {
    Square sq;
    Load pressure;
    pressure.type = LoadType::Pressure;
    pressure.elements = {0, 1};
    pressure.pressure = 3.0;
    Load force;
    force.type = LoadType::Force;
    force.nodes = {3};
    force.vector = Vec3(1, 2, 0);
    force.curve = 0;
    Load moment;
    moment.type = LoadType::Moment;
    moment.nodes = {1};
    moment.vector = Vec3(0, 0, 5);
    sq.model.loads = {pressure, force, moment};
    const MeshTopology topology(sq.model);
    ExternalLoads loads(sq.model, topology);
    EXPECT_TRUE(loads.has_moment_loads());
    const BoundaryConditions bc(sq.model, std::vector<std::uint8_t>(4, 0));
    ParticleState s = state_of(sq.model);
    loads.update_normals_and_loads(s, bc, 0.5, false);
    Vec3 total = Vec3::Zero();
    for (const Vec3& f : s.f_ext) total += f;
    // -p A n (A = 1, n = +z) plus the ramp's 0.5 times the nodal force
    EXPECT_NEAR((total - (Vec3(0, 0, -3.0) + 0.5 * force.vector)).norm(), 0.0, 1e-14);
    EXPECT_NEAR(s.f_ext[1].z(), -3.0 * 0.5 / 3.0, 1e-15);  // corner 1: a third of triangle 0
    EXPECT_EQ(s.m_ext[1], moment.vector);
    for (const Vec3& n : s.normal) EXPECT_NEAR((n - Vec3::UnitZ()).norm(), 0.0, 1e-15);
    EXPECT_NEAR((s.drill_axis[0] - Vec3::UnitZ()).norm(), 0.0, 1e-15);

    // Turned by 90 degrees about x: the pressure follows the surface (now along +y).
    const Mat3 turn = rotation_matrix(Vec3(0.5 * 3.14159265358979323846, 0, 0));
    for (std::size_t p = 0; p < s.size(); ++p) s.x[p] = turn * sq.model.nodes[p];
    const std::vector<Vec3> before = s.f_ext;
    loads.update_normals_and_loads(s, bc, 0.5, false);
    EXPECT_EQ(s.f_ext_prev, before);
    Vec3 turned = Vec3::Zero();
    for (const Vec3& f : s.f_ext) turned += f;
    EXPECT_NEAR((turned - (turn * Vec3(0, 0, -3.0) + 0.5 * force.vector)).norm(), 0.0, 1e-14);
}
