// The model most unit tests start from: a generated mesh with every triangle in one elastic
// steel section (rho = 7800 kg/m^3, E = 2.1e11 Pa unless given). Tests add their boundary
// conditions, loads and initial velocities.
#pragma once

#include <array>

#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/mesh/mesh_data.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell::test {

inline Model one_section_model(const MeshData& mesh, Real thickness, Real poisson_ratio = 0.3,
                               Real youngs_modulus = 2.1e11, int thickness_points = 2,
                               int inplane_points = 3) {
    Model m;
    m.nodes = mesh.nodes;
    m.triangles = mesh.triangles;
    m.node_sets = mesh.node_sets;
    m.materials.push_back({"steel", "elastic", 7800, youngs_modulus, poisson_ratio});
    m.sections.push_back({0, thickness, thickness_points, inplane_points});
    m.element_section.assign(m.triangles.size(), 0);
    return m;
}

/// A square plate of n x n squares, each cut into two triangles with alternating diagonals, in
/// one section of thickness h.
inline Model alternate_plate(Index n, Real thickness = 0.002) {
    PlateParams pp;
    pp.nx = pp.ny = n;
    pp.pattern = DiagonalPattern::Alternate;
    return one_section_model(generate_plate(pp), thickness);
}

/// Every particle of m moved at its own constant velocity velocity(x0) (a homogeneous path when
/// the field is linear): one prescribed-velocity entry per particle, of the translation
/// `components`, with the degrees of freedom `fixed` held.
template <class VelocityField>
void prescribe_velocity_field(Model& m, const VelocityField& velocity, std::array<bool, 6> fixed,
                              std::array<bool, 3> components = {true, true, true}) {
    for (Index p = 0; p < m.n_particles(); ++p) {
        BoundaryCondition moved;
        moved.nodes = {p};
        moved.fixed = fixed;
        moved.prescribed = PrescribedKind::Velocity;
        moved.value = velocity(m.nodes[static_cast<std::size_t>(p)]);
        moved.components = components;
        m.boundary.push_back(moved);
    }
}

}  // namespace fpmshell::test
