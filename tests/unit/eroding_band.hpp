// A plate torn in two by erosion (theory.md §7.6), for the erosion tests: a 1 m square steel
// plate of n x n squares (h = 1 cm, J2 with linear hardening) held flat, its edges x = 0 and
// x = 1 pulled apart at 20 m/s each. The elements whose centres lie within 5 cm of x = 0.5 are
// of a steel that fails at a plastic strain of 5 %; the others cannot fail. The band erodes
// from about 1.3 ms on (a strain rate of 40 /s), and the halves fly apart.
#pragma once

#include <cmath>

#include "fpmshell/failure/johnson_cook/johnson_cook_damage.hpp"
#include "fpmshell/failure/plastic_strain/plastic_strain_failure.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "one_section_model.hpp"

namespace fpmshell::test {

/// The plate above, its band failing by Johnson-Cook damage instead (failure/johnson_cook:
/// eps_f = 0.058 in uniaxial tension at the band's rate) where `damage`.
inline Model eroding_band_plate(Index n, bool damage = false) {
    PlateParams pp;
    pp.nx = pp.ny = n;
    pp.pattern = DiagonalPattern::Alternate;
    Model m = one_section_model(generate_plate(pp), 0.01, 0.3, 2.1e11, 3);
    Material& steel = m.materials[0];
    make_bilinear(steel, 2.5e8, 1.0e9);
    Material weak = steel;
    weak.name = "weak";
    if (damage)
        weak.failure.criteria.push_back(
            {"johnson_cook", JohnsonCookDamageParameters{0.01, 0.08, -1.5, 0.01, 0.0, 1.0, 1e-6}});
    else
        add_plastic_strain_failure(weak, 0.05);
    m.materials.push_back(weak);
    m.sections.push_back(m.sections[0]);
    m.sections[1].material = 1;
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
        Real xc = 0;
        for (const Index p : m.triangles[e]) xc += m.nodes[static_cast<std::size_t>(p)].x() / 3;
        if (std::abs(xc - 0.5) < 0.05) m.element_section[e] = 1;
    }
    BoundaryCondition flat;
    for (Index p = 0; p < m.n_particles(); ++p) flat.nodes.push_back(p);
    flat.fixed = {false, false, true, true, true, false};
    m.boundary.push_back(flat);
    for (const Real side : {-1.0, 1.0}) {
        BoundaryCondition pulled;
        pulled.nodes = m.node_sets.at(side < 0 ? "xmin" : "xmax");
        pulled.prescribed = PrescribedKind::Velocity;
        pulled.value = Vec3(20.0 * side, 0, 0);
        pulled.components = {true, false, false};
        m.boundary.push_back(pulled);
    }
    m.control.end_time = 2.0e-3;
    return m;
}

}  // namespace fpmshell::test
