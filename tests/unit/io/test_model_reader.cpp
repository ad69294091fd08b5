// Unit tests of the YAML model reader (io/model_reader.hpp): a complete model is read into the
// documented Model fields, with the defaults; its errors are in test_model_reader_errors.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/materials/j2/j2_parameters.hpp"
#include "io/model_reader_fixture.hpp"

namespace fpmshell {
namespace {

using test::expect_error;
using test::expect_override_error;
using test::k_base;
using test::replaced;
using test::TempDir;

// A model using every block is read into the documented Model fields: sets (generator, near
// with and without tolerance, plane, box), the section override rule, boundary kinds, loads,
// curves, initial conditions, damping, control and output.
TEST(ModelReader, ReadsACompleteModel) {
    const TempDir dir;
    const std::string file = dir.write("full.yaml", R"(title: Full model
mesh:
  generator: plate
  length_x: 2
  length_y: 1
  nx: 4
  ny: 2
sets:
  corner: {near: [2, 1, 0]}
  middle: {near: [1, 0.5, 0], tolerance: 0.6}
  x0: {plane: {point: [0, 0, 0], normal: [2, 0, 0]}}
  left_half: {box: [[-1, -1, -1], [1, 2, 1]]}
materials:
  steel: {type: elastic, density: 7.8e-9, youngs_modulus: 210000, poisson_ratio: 0.3}
  soft: {type: elastic, density: 1e-9, youngs_modulus: 1000, poisson_ratio: -0.2}
sections:
  - {elements: all, material: steel, thickness: 0.1}
  - {elements: left_half, material: soft, thickness: 0.2, thickness_points: 5, inplane_points: 7}
boundary:
  - {nodes: xmin, fix: all}
  - {nodes: ymin, fix: [uz, rx]}
  - {nodes: x0, symmetry: x}
  - {nodes: xmax, symmetry: y, prescribe: {velocity: [1, 0, 0], curve: ramp}}
  - {nodes: corner, prescribe: {angular_velocity: [0, 0, 3]}}
curves:
  ramp: [[0, 0], [1.0e-3, 1]]
  step: [[0, 1]]
loads:
  - {type: pressure, elements: all, value: 600, curve: step}
  - {type: force, nodes: corner, value: [0, 0, -1]}
  - {type: moment, nodes: corner, value: [0, 1, 0], curve: ramp}
initial_conditions:
  - {nodes: middle, velocity: [0, 0, -5]}
  - {nodes: corner, angular_velocity: [1, 2, 3]}
damping: {mass: 2.0}
control:
  end_time: 1.0e-3
  time_step_scale: 0.5
  mode: relaxation
  tolerance: 1.0e-4
  bending: dkt
  energy_error_limit: 0.1
  max_relaxation_iterations: 1000
output:
  every: 1.0e-5
  histories:
    - {name: tip_w, nodes: corner, quantity: uz}
    - {name: edge_fz, nodes: xmin, quantity: reaction_z, reduce: sum}
)");
    const Model m = read_model(file);
    EXPECT_EQ(m.title, "Full model");
    EXPECT_EQ(m.source_file, file);
    EXPECT_EQ(m.n_particles(), 15);
    EXPECT_EQ(m.n_elements(), 16);

    using V = std::vector<Index>;
    EXPECT_EQ(m.node_sets.at("corner"), (V{14}));
    EXPECT_EQ(m.node_sets.at("middle"), (V{2, 6, 7, 8, 12}));
    EXPECT_EQ(m.element_sets.at("middle").size(), 2U);  // the two triangles inside the 5 nodes
    EXPECT_EQ(m.node_sets.at("x0"), (V{0, 5, 10}));
    EXPECT_TRUE(m.element_sets.at("x0").empty());
    EXPECT_EQ(m.node_sets.at("left_half").size(), 9U);
    EXPECT_EQ(m.element_sets.at("left_half").size(), 8U);  // centroids with x <= 1
    EXPECT_EQ(m.node_sets.at("all").size(), 15U);
    EXPECT_EQ(m.element_sets.at("all").size(), 16U);
    for (const char* name : {"xmin", "xmax", "ymin", "ymax", "boundary"})
        EXPECT_EQ(m.node_sets.count(name), 1U) << name;

    ASSERT_EQ(m.materials.size(), 2U);
    EXPECT_EQ(m.materials[1].name, "soft");
    EXPECT_EQ(m.materials[1].poisson_ratio, -0.2);
    EXPECT_EQ(m.materials[0].density, 7.8e-9);
    ASSERT_EQ(m.sections.size(), 2U);
    EXPECT_EQ(m.sections[1].material, 1);
    EXPECT_EQ(m.sections[1].thickness_points, 5);
    EXPECT_EQ(m.sections[1].inplane_points, 7);
    EXPECT_EQ(m.sections[0].thickness_points, 2);
    EXPECT_EQ(m.sections[0].inplane_points, 3);
    // The later section entry wins on the elements it shares with the earlier one.
    for (Index e = 0; e < m.n_elements(); ++e) {
        const auto& half = m.element_sets.at("left_half");
        const bool in_half = std::binary_search(half.begin(), half.end(), e);
        EXPECT_EQ(m.element_section[static_cast<std::size_t>(e)], in_half ? 1 : 0);
    }

    ASSERT_EQ(m.boundary.size(), 5U);
    EXPECT_EQ(m.boundary[0].fixed, (std::array<bool, 6>{true, true, true, true, true, true}));
    EXPECT_EQ(m.boundary[1].fixed, (std::array<bool, 6>{false, false, true, true, false, false}));
    EXPECT_EQ(m.boundary[2].fixed, (std::array<bool, 6>{true, false, false, false, true, true}));
    EXPECT_EQ(m.boundary[3].fixed, (std::array<bool, 6>{false, true, false, true, false, true}));
    EXPECT_EQ(m.boundary[3].prescribed, PrescribedKind::Velocity);
    EXPECT_EQ(m.boundary[3].value, Vec3(1, 0, 0));
    EXPECT_EQ(m.boundary[3].curve, 0);
    EXPECT_EQ(m.boundary[4].prescribed, PrescribedKind::AngularVelocity);
    EXPECT_EQ(m.boundary[4].curve, -1);
    EXPECT_EQ(m.boundary[0].nodes, (V{0, 5, 10}));

    ASSERT_EQ(m.curves.size(), 2U);
    EXPECT_EQ(m.curves[0].name, "ramp");
    EXPECT_DOUBLE_EQ(m.curves[0].value(0.5e-3), 0.5);

    ASSERT_EQ(m.loads.size(), 3U);
    EXPECT_EQ(m.loads[0].type, LoadType::Pressure);
    EXPECT_EQ(m.loads[0].pressure, 600.0);
    EXPECT_EQ(m.loads[0].elements.size(), 16U);
    EXPECT_EQ(m.loads[0].curve, 1);
    EXPECT_EQ(m.loads[1].type, LoadType::Force);
    EXPECT_EQ(m.loads[1].vector, Vec3(0, 0, -1));
    EXPECT_EQ(m.loads[1].curve, -1);
    EXPECT_EQ(m.loads[2].type, LoadType::Moment);
    EXPECT_EQ(m.loads[2].nodes, (V{14}));

    ASSERT_EQ(m.initial_conditions.size(), 2U);
    EXPECT_EQ(m.initial_conditions[0].velocity, Vec3(0, 0, -5));
    EXPECT_EQ(m.initial_conditions[0].nodes.size(), 5U);
    EXPECT_EQ(m.initial_conditions[1].angular_velocity, Vec3(1, 2, 3));
    EXPECT_EQ(m.initial_conditions[1].velocity, Vec3::Zero());

    EXPECT_EQ(m.damping.mass, 2.0);
    EXPECT_EQ(m.damping.stiffness, 0.0);
    EXPECT_EQ(m.control.end_time, 1.0e-3);
    EXPECT_EQ(m.control.time_step_scale, 0.5);
    EXPECT_EQ(m.control.mode, SolutionMode::Relaxation);
    EXPECT_EQ(m.control.tolerance, 1.0e-4);
    EXPECT_EQ(m.control.bending, BendingKernel::Dkt);
    EXPECT_EQ(m.control.energy_error_limit, 0.1);
    EXPECT_EQ(m.control.max_relaxation_iterations, 1000);
    EXPECT_EQ(m.output.every, 1.0e-5);
    EXPECT_DOUBLE_EQ(m.output.fields_every, 1.0e-3 / 20);
    ASSERT_EQ(m.output.histories.size(), 2U);
    EXPECT_EQ(m.output.histories[0].reduce, Reduce::Single);
    EXPECT_EQ(m.output.histories[0].quantity, Quantity::Uz);
    EXPECT_EQ(m.output.histories[1].reduce, Reduce::Sum);
    EXPECT_EQ(m.output.histories[1].quantity, Quantity::ReactionZ);
    EXPECT_EQ(m.output.histories[1].nodes.size(), 3U);
}

// Defaults: title = file stem, control and output defaults of model-format.md, no damping.
TEST(ModelReader, AppliesDefaults) {
    const TempDir dir;
    const Model m = read_model(dir.write("my_case.yaml", replaced(k_base, "title: t\n", "")));
    EXPECT_EQ(m.title, "my_case");
    EXPECT_EQ(m.control.time_step_scale, 0.9);
    EXPECT_EQ(m.control.mode, SolutionMode::Dynamic);
    EXPECT_EQ(m.control.tolerance, 1e-5);
    EXPECT_EQ(m.control.bending, BendingKernel::Dkt);
    EXPECT_EQ(m.control.energy_error_limit, 0.5);
    EXPECT_EQ(m.control.max_relaxation_iterations, 200000);
    EXPECT_DOUBLE_EQ(m.output.every, 1.0e-3 / 200);
    EXPECT_DOUBLE_EQ(m.output.fields_every, 1.0e-3 / 20);
    EXPECT_EQ(m.damping.mass, 0.0);
    EXPECT_TRUE(m.boundary.empty());
    EXPECT_TRUE(m.loads.empty());
    EXPECT_EQ(m.element_section, std::vector<Index>(16, 0));
    EXPECT_FALSE(m.control.thickness_update);
    EXPECT_EQ(m.sections[0].thickness_points, 2);  // elastic: 2 Gauss x 3 points
    EXPECT_EQ(m.sections[0].inplane_points, 3);
}

// Plastic materials: every constant lands in the model, plastic sections default to
// 5 Lobatto x 7 points (theory.md §7.5), explicit point counts win.
TEST(ModelReader, ReadsPlasticMaterials) {
    const TempDir dir;
    const std::string steel =
        "steel: {type: elastic, density: 7.8e-9, youngs_modulus: 210000, poisson_ratio: 0.3}";
    const Model j2 = read_model(dir.write(
        "j2.yaml",
        replaced(replaced(k_base, steel,
                          "steel: {type: j2_plastic, density: 7.8e-9, youngs_modulus: 210000, "
                          "poisson_ratio: 0.3, yield_stress: 250, tangent_modulus: 2100, "
                          "hardening_mix: 0.5, cowper_symonds: {D: 40.4, q: 5}}"),
                 "  end_time: 1.0e-3\n", "  end_time: 1.0e-3\n  thickness_update: true\n")));
    const Material& m = j2.materials[0];
    EXPECT_EQ(m.law, "j2_plastic");
    const J2Parameters& mp = *j2_parameters(m);
    EXPECT_EQ(mp.flow.yield_stress, 250);
    EXPECT_DOUBLE_EQ(mp.flow.hardening,
                     210000.0 * 2100 / (210000.0 - 2100));  // H = E E_t / (E - E_t)
    EXPECT_EQ(mp.hardening_mix, 0.5);
    EXPECT_EQ(mp.rate.kind, RateFactor::Kind::CowperSymonds);
    EXPECT_EQ(mp.rate.d, 40.4);
    EXPECT_EQ(mp.rate.q, 5);
    EXPECT_TRUE(j2.control.thickness_update);
    EXPECT_EQ(j2.sections[0].thickness_points, 5);
    EXPECT_EQ(j2.sections[0].inplane_points, 3);

    const Model jc = read_model(dir.write(
        "jc.yaml",
        replaced(replaced(k_base, steel,
                          "steel: {type: johnson_cook, density: 7.8e-9, youngs_modulus: 210000, "
                          "poisson_ratio: 0.3, A: 350, B: 275, n: 0.36, C: 0.022, "
                          "reference_strain_rate: 1, hardening_mix: 0.5}"),
                 "thickness: 0.1}", "thickness: 0.1, thickness_points: 3, inplane_points: 3}")));
    const Material& c = jc.materials[0];
    EXPECT_EQ(c.law, "johnson_cook");
    const J2Parameters& cp = *j2_parameters(c);
    EXPECT_EQ(cp.flow.kind, FlowStress::Kind::JohnsonCook);
    EXPECT_EQ(cp.flow.a, 350);
    EXPECT_EQ(cp.flow.b, 275);
    EXPECT_EQ(cp.flow.n, 0.36);
    EXPECT_EQ(cp.rate.kind, RateFactor::Kind::JohnsonCook);
    EXPECT_EQ(cp.rate.c, 0.022);
    EXPECT_EQ(cp.rate.reference_rate, 1);
    EXPECT_EQ(cp.hardening_mix, 0.5);
    EXPECT_EQ(jc.sections[0].thickness_points, 3);
    EXPECT_EQ(jc.sections[0].inplane_points, 3);

    const Model tab = read_model(dir.write(
        "tab.yaml", replaced(k_base, steel,
                             "steel: {type: tabulated, density: 7.8e-9, youngs_modulus: 210000, "
                             "poisson_ratio: 0.3, flow_curve: [[0, 250], [0.02, 300], [0.3, "
                             "300]], hardening_mix: 0.5, cowper_symonds: {D: 40.4, q: 5}}")));
    const Material& t = tab.materials[0];
    EXPECT_EQ(t.law, "tabulated");
    const J2Parameters& tp = *j2_parameters(t);
    ASSERT_EQ(tp.flow.table.size(), 1U);
    EXPECT_EQ(tp.flow.value(0), 250);
    EXPECT_NEAR(tp.flow.value(0.01), 275, 1e-9);  // halfway along the first segment
    EXPECT_EQ(tp.flow.value(0.3), 300);
    EXPECT_EQ(tp.hardening_mix, 0.5);
    EXPECT_EQ(tp.rate.kind, RateFactor::Kind::CowperSymonds);
    EXPECT_EQ(tp.rate.q, 5);
    EXPECT_EQ(tab.sections[0].thickness_points, 5);

    const Model rates = read_model(dir.write(
        "rates.yaml",
        replaced(k_base, steel,
                 "steel: {type: tabulated, density: 7.8e-9, youngs_modulus: 210000, "
                 "poisson_ratio: 0.3, flow_curves: [{strain_rate: 0, points: [[0, 250], [0.2, "
                 "300]]}, {strain_rate: 100, points: [[0, 300], [0.1, 330], [0.3, 380]]}]}")));
    const J2Parameters& r = *j2_parameters(rates.materials[0]);
    ASSERT_EQ(r.flow.table.size(), 2U);
    EXPECT_EQ(r.flow.table.rates(), (std::vector<Real>{0, 100}));
    EXPECT_EQ(r.rate.kind, RateFactor::Kind::Table);
    EXPECT_NEAR(r.flow.table.at(0.1, 1.0).value, 330, 1e-9);  // position 1: the second curve
    EXPECT_NEAR(r.flow.table.at(0.2, 1.0).value, 355, 1e-9);
    EXPECT_EQ(r.hardening_mix, 1);
}

// Each generator is reachable from the model file with its keys, and its sets are usable.
TEST(ModelReader, ReadsEveryGenerator) {
    const TempDir dir;
    auto read_mesh = [&](const std::string& mesh) {
        return read_model(dir.write(
            "gen.yaml",
            replaced(k_base, "mesh: {generator: plate, length_x: 2, length_y: 1, nx: 4, ny: 2}",
                     mesh)));
    };
    const Model cap = read_mesh(
        "mesh: {generator: spherical_cap, radius: 22.27, half_angle_deg: "
        "26.67, sector_deg: 90, divisions: 12}");
    EXPECT_EQ(cap.n_particles(), 1 + 12 * 13 + 12);
    EXPECT_EQ(cap.node_sets.count("edge0"), 1U);
    const Model hex = read_mesh(
        "mesh: {generator: spherical_cap, radius: 22.27, half_angle_deg: "
        "26.67, divisions: 6}");
    EXPECT_EQ(hex.n_particles(), 127);
    const Model cyl = read_mesh(
        "mesh: {generator: cylinder_panel, radius: 300, length: 600, "
        "angle_deg: 80, divisions_arc: 4, divisions_length: 3, "
        "pattern: alternate}");
    EXPECT_EQ(cyl.n_particles(), 20);
    EXPECT_EQ(cyl.node_sets.count("arc1"), 1U);
    const Model tube = read_mesh(
        "mesh: {generator: cylinder_panel, radius: 1, length: 2, "
        "angle_deg: 360, divisions_arc: 6, divisions_length: 2}");
    EXPECT_EQ(tube.n_particles(), 18);
    const Model ring = read_mesh(
        "mesh: {generator: annulus, inner_radius: 6, outer_radius: 10, "
        "divisions_radial: 2, divisions_angle: 8, pattern: cross}");
    EXPECT_EQ(ring.n_particles(), 3 * 9 + 16);
    EXPECT_EQ(ring.node_sets.at("edge1").size(), 3U);
    const Model plate = read_mesh(
        "mesh: {generator: plate, length_x: 1, length_y: 1, nx: 2, "
        "ny: 1, origin: [0, 0, 5], pattern: left}");
    EXPECT_EQ(plate.nodes[0].z(), 5.0);
}

// A mesh file is found relative to the model file; its physical groups become sets that the
// model can use, and a degenerate element in it is reported with its number and key `mesh`.
TEST(ModelReader, ReadsAGmshFileAndRefusesDegenerateElements) {
    const TempDir dir;
    const std::string msh = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 1 "clamp"
2 2 "skin"
$EndPhysicalNames
$Nodes
4
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
$EndNodes
$Elements
3
1 1 2 1 1 1 4
2 2 2 2 1 1 2 3
3 2 2 2 1 1 3 4
$EndElements
)";
    (void)dir.write("plate.msh", msh);
    const std::string yaml =
        replaced(k_base, "mesh: {generator: plate, length_x: 2, length_y: 1, nx: 4, ny: 2}",
                 "mesh: {file: plate.msh}\nboundary:\n  - {nodes: clamp, fix: all}");
    const Model m = read_model(dir.write("model.yaml", yaml));
    EXPECT_EQ(m.n_particles(), 4);
    EXPECT_EQ(m.n_elements(), 2);
    EXPECT_EQ(m.boundary[0].nodes, (std::vector<Index>{0, 3}));
    EXPECT_EQ(m.element_sets.at("skin").size(), 2U);

    (void)dir.write("plate.msh", replaced(msh, "3 2 2 2 1 1 3 4", "3 2 2 2 1 1 2 2"));
    expect_error(
        replaced(k_base, "mesh: {generator: plate, length_x: 2, length_y: 1, nx: 4, ny: 2}",
                 "mesh: {file: " + dir.path("plate.msh") + "}"),
        2, "mesh", "element 2 (number 3 in the mesh file) is degenerate");
}

// Sets of node_ids and element_ids: the mesh file's numbers (an LS-DYNA file here); a number
// the mesh does not have, a tolerance, and a generated mesh (no numbers) are refused.
TEST(ModelReader, ReadsSetsOfNodeNumbers) {
    const TempDir dir;
    const std::string k_file = dir.write("plate.k", R"(*NODE
      10             0.0             0.0             0.0
      20             1.0             0.0             0.0
      30             1.0             1.0             0.0
      40             0.0             1.0             0.0
      50             5.0             5.0             0.0
*ELEMENT_SHELL
       1       1      10      20      30      40
)");
    const std::string mesh_line =
        "mesh: {generator: plate, length_x: 2, length_y: 1, nx: 4, ny: 2}";
    const std::string yaml = replaced(
        k_base, mesh_line, "mesh: {file: " + k_file + "}\nsets:\n  corners: {node_ids: [40, 10]}");
    const Model m = read_model(dir.write("model.yaml", yaml));
    EXPECT_EQ(m.node_sets.at("corners"), (std::vector<Index>{0, 3}));
    EXPECT_TRUE(m.element_sets.at("corners").empty());
    expect_error(replaced(yaml, "[40, 10]", "[40, 11]"), 4, "sets.corners.node_ids.1",
                 "node 11 is not a node of the mesh's shells");
    expect_error(replaced(yaml, "[40, 10]", "[50]"), 4, "sets.corners.node_ids.0",
                 "node 50 is not a node of the mesh's shells");
    expect_error(replaced(yaml, "[40, 10]}", "[40], tolerance: 1}"), 4, "sets.corners.tolerance",
                 "takes no tolerance");
    expect_error(replaced(k_base, mesh_line, mesh_line + "\nsets:\n  a: {node_ids: [1]}"), 4,
                 "sets.a.node_ids", "needs a mesh file with node numbers");
    const Model e = read_model(
        dir.write("model.yaml", replaced(yaml, "node_ids: [40, 10]", "element_ids: [1]")));
    EXPECT_EQ(e.element_sets.at("corners"), (std::vector<Index>{0, 1}));  // both halves
    EXPECT_EQ(e.node_sets.at("corners"), (std::vector<Index>{0, 1, 2, 3}));
    expect_error(replaced(yaml, "node_ids: [40, 10]", "element_ids: [2]"), 4,
                 "sets.corners.element_ids.0", "element 2 is not a shell element");
}

// prescribe.components: the translation components a displacement or velocity prescribes.
TEST(ModelReader, ReadsPrescribedComponents) {
    const std::string yaml =
        k_base +
        "boundary:\n  - {nodes: xmax, prescribe: {velocity: [1, 0, 0], components: [ux, uz]}}\n";
    const TempDir dir;
    const Model m = read_model(dir.write("model.yaml", yaml));
    EXPECT_EQ(m.boundary[0].components, (std::array<bool, 3>{true, false, true}));
    expect_error(replaced(yaml, "[ux, uz]", "[ux, rz]"), 10, "boundary.0.prescribe.components.1",
                 "rz");
    expect_error(replaced(yaml, "[ux, uz]", "[]"), 10, "boundary.0.prescribe.components",
                 "non-empty list");
    expect_error(replaced(yaml, "velocity: [1, 0, 0]", "angular_velocity: [1, 0, 0]"), 10,
                 "boundary.0.prescribe.components", "about all three axes");
}

// power_law (eq. 7.2-6): eps_0 from yield_stress, or where the elastic line meets k eps^n.
TEST(ModelReader, ReadsPowerLawMaterials) {
    const std::string elastic =
        "steel: {type: elastic, density: 7.8e-9, youngs_modulus: 210000, poisson_ratio: 0.3}";
    const std::string power =
        "steel: {type: power_law, density: 7.8e-9, youngs_modulus: 210000, poisson_ratio: 0.3, "
        "k: 900, n: 0.25}";
    const TempDir dir;
    const Model m = read_model(dir.write("model.yaml", replaced(k_base, elastic, power)));
    const Material& mat = m.materials[0];
    EXPECT_EQ(mat.law, "power_law");
    const FlowStress& flow = j2_parameters(mat)->flow;
    const Real eps0 = std::pow(900.0 / 210000.0, 1.0 / 0.75);  // E eps = k eps^n
    EXPECT_NEAR(flow.strain_offset, eps0, 1e-15);
    EXPECT_NEAR(flow.value(0), 210000.0 * eps0, 1e-9);
    const Model y = read_model(dir.write(
        "model.yaml",
        replaced(k_base, elastic, replaced(power, "n: 0.25", "n: 0.25, yield_stress: 300"))));
    EXPECT_NEAR(j2_parameters(y.materials[0])->flow.strain_offset, std::pow(300.0 / 900.0, 4.0),
                1e-15);
    expect_error(replaced(k_base, elastic, replaced(power, "n: 0.25", "n: 1.5")), 4,
                 "materials.steel.n", "must be below 1 without a yield_stress");
    expect_error(replaced(k_base, elastic, replaced(power, "k: 900", "k: -1")), 4,
                 "materials.steel.k", "greater than 0");
    expect_error(replaced(k_base, elastic, replaced(elastic, "}", ", k: 900}")), 4,
                 "materials.steel.k", "belongs to plastic materials");
}

// contact.elements of a self-contact: one set, or a list of sets (their union).
TEST(ModelReader, ReadsSelfContactOverSeveralSets) {
    const std::string yaml =
        k_base +
        "sets:\n  a: {box: [[0, 0, -1], [0.6, 1, 1]]}\n  b: {box: [[1.4, 0, -1], [2, 1, 1]]}\n"
        "contact:\n  - {type: self, elements: [a, b]}\n";
    const TempDir dir;
    const Model m = read_model(dir.write("model.yaml", yaml));
    std::vector<Index> both = m.element_sets.at("a");
    both.insert(both.end(), m.element_sets.at("b").begin(), m.element_sets.at("b").end());
    std::sort(both.begin(), both.end());
    ASSERT_FALSE(m.element_sets.at("a").empty());
    EXPECT_EQ(m.contacts[0].elements, both);
    expect_error(replaced(yaml, "[a, b]", "[]"), 13, "contact.0.elements", "non-empty list");
    expect_error(replaced(yaml, "[a, b]", "[a, c]"), 13, "contact.0.elements.1", "c");
}

// contact.friction of a rigid contact: a Coulomb coefficient, or `stick` (no sliding).
TEST(ModelReader, ReadsTheFrictionOfARigidContact) {
    const std::string yaml =
        k_base +
        "rigid_bodies:\n  - {name: w, fixed: true, point: [0, 0, -1], normal: [0, 0, 1]}\n"
        "contact:\n  - {type: rigid, body: w, friction: 0.25}\n";
    const TempDir dir;
    EXPECT_EQ(read_model(dir.write("model.yaml", yaml)).contacts[0].friction, 0.25);
    EXPECT_EQ(
        read_model(dir.write("stick.yaml", replaced(yaml, "0.25", "stick"))).contacts[0].friction,
        std::numeric_limits<Real>::infinity());
    EXPECT_EQ(read_model(dir.write("none.yaml", replaced(yaml, ", friction: 0.25", "")))
                  .contacts[0]
                  .friction,
              0.0);
    // LS-DYNA's decay (theory.md eq. 8.4-5), on a rigid and on a self-contact
    const std::string decay = ", friction: 0.25, friction_dynamic: 0.1, friction_decay: 5";
    const Model d = read_model(dir.write("decay.yaml", replaced(yaml, ", friction: 0.25", decay)));
    EXPECT_EQ(d.contacts[0].friction_dynamic, 0.1);
    EXPECT_EQ(d.contacts[0].friction_decay, 5.0);
    const std::string self = k_base + "contact:\n  - {type: self" + decay + "}\n";
    EXPECT_EQ(read_model(dir.write("self.yaml", self)).contacts[0].friction_decay, 5.0);
    expect_error(replaced(self, ", friction_decay: 5", ""), -1, "contact.0.friction_dynamic",
                 "needs friction_decay");
    expect_error(replaced(self, "friction: 0.25", "friction: stick"), -1,
                 "contact.0.friction_dynamic", "a number friction > 0");
}

// constraints of type rigid: the particles of a node set move as one rigid body.
TEST(ModelReader, ReadsNodalRigidBodies) {
    const std::string yaml = k_base +
                             "sets:\n  weld: {box: [[0.9, -1, -1], [1.1, 0.6, 1]]}\n"
                             "constraints:\n  - {type: rigid, nodes: weld}\n";
    const TempDir dir;
    const Model m = read_model(dir.write("model.yaml", yaml));
    ASSERT_EQ(m.nodal_rigid_bodies.size(), 1u);
    EXPECT_EQ(m.nodal_rigid_bodies[0].nodes, m.node_sets.at("weld"));
    EXPECT_EQ(m.nodal_rigid_bodies[0].nodes.size(), 2u);  // x = 1, y = 0 and 0.5
    expect_error(replaced(yaml, "0.6, 1]", "0.1, 1]"), 12, "constraints.0.nodes",
                 "a rigid body needs at least two particles, the set 'weld' has 1");
    expect_error(replaced(yaml, "type: rigid", "type: glued"), 12, "constraints.0.type",
                 "expected one of rigid, tied");
    // a tie needs the faces it ties to
    expect_error(replaced(yaml, "type: rigid", "type: tied"), 12, "constraints.0.elements",
                 "is required");
    expect_error(yaml + "boundary:\n  - {nodes: weld, fix: [uz]}\n", 12, "constraints.0.nodes",
                 "of the rigid body also has a boundary condition");
}

// type: rigid: an elastic material whose sections move as rigid bodies.
TEST(ModelReader, ReadsRigidMaterials) {
    const std::string yaml =
        replaced(k_base, "sections:\n",
                 "  hammer: {type: rigid, density: 7.8e-9, youngs_modulus: 210000, "
                 "poisson_ratio: 0.3}\nsections:\n") +
        "sets:\n  head: {box: [[1.4, -1, -1], [2.1, 2, 1]]}\n";
    const std::string with_section =
        replaced(yaml, "  - {elements: all, material: steel, thickness: 0.1}\n",
                 "  - {elements: all, material: steel, thickness: 0.1}\n"
                 "  - {elements: head, material: hammer, thickness: 0.1}\n");
    const TempDir dir;
    const Model m = read_model(dir.write("model.yaml", with_section));
    ASSERT_EQ(m.materials.size(), 2u);
    EXPECT_TRUE(m.materials[1].rigid);
    EXPECT_FALSE(m.materials[0].rigid);
    EXPECT_EQ(m.materials[1].law, "rigid");
    EXPECT_FALSE(m.materials[1].plastic());
    expect_error(replaced(with_section, "material: steel", "material: hammer"), 6, "sections",
                 "every element is in a section of a rigid material");
    expect_error(with_section + "boundary:\n  - {nodes: xmax, fix: all}\n", 14, "boundary.0.nodes",
                 "belongs to a section of the rigid material 'hammer'");
    expect_error(replaced(with_section, "poisson_ratio: 0.3}\nsections",
                          "poisson_ratio: 0.3, "
                          "yield_stress: 1}\nsections"),
                 5, "materials.hammer.yield_stress", "belongs to plastic materials");
}

// contact_<n>_force_<c>: the force on the slaves of the n-th contact definition.
TEST(ModelReader, ReadsContactForceHistories) {
    const std::string yaml = k_base +
                             "contact:\n  - {type: self}\noutput:\n  histories:\n"
                             "    - {name: f, quantity: contact_1_force_y}\n";
    const TempDir dir;
    const Model m = read_model(dir.write("model.yaml", yaml));
    ASSERT_EQ(m.output.histories.size(), 1u);
    EXPECT_EQ(m.output.histories[0].contact, 0);
    EXPECT_EQ(m.output.histories[0].quantity, Quantity::ContactForceY);
    expect_error(replaced(yaml, "contact_1", "contact_2"), 13, "output.histories.0.quantity",
                 "names contact definition 2, but the model has 1");
    expect_error(replaced(yaml, "force_y", "force_q"), 13, "output.histories.0.quantity",
                 "expected contact_<n>_force_x, _y or _z");
    expect_error(replaced(yaml, "quantity: contact", "nodes: all, quantity: contact"), 13,
                 "output.histories.0.nodes", "belongs to the contact definition");
}

// control.rotary_inertia and control.mass_scaling (theory.md §6.2, §6.10): the words and the
// numbers land in Control, the defaults are the option-B inertia and no mass scaling, and a bad
// value names the file, the line and the key.
TEST(ModelReader, ReadsRotaryInertiaAndMassScaling) {
    const TempDir dir;
    const Model plain = read_model(dir.write("plain.yaml", k_base));
    EXPECT_EQ(plain.control.rotary_inertia, RotaryInertia::Belytschko);
    EXPECT_EQ(plain.control.mass_scaling.time_step, 0.0);
    EXPECT_EQ(plain.control.mass_scaling.added_mass_limit, 0.05);
    for (const auto& [word, kind] : {std::pair{"belytschko", RotaryInertia::Belytschko},
                                     std::pair{"abaqus", RotaryInertia::Abaqus},
                                     std::pair{"radioss", RotaryInertia::Radioss}}) {
        const Model m = read_model(
            dir.write(std::string(word) + ".yaml", k_base + "  rotary_inertia: " + word + "\n"));
        EXPECT_EQ(m.control.rotary_inertia, kind) << word;
    }
    const Model scaled = read_model(dir.write(
        "scaled.yaml", k_base + "  mass_scaling: {time_step: 2.5e-7, added_mass_limit: 0.1}\n"));
    EXPECT_EQ(scaled.control.mass_scaling.time_step, 2.5e-7);
    EXPECT_EQ(scaled.control.mass_scaling.added_mass_limit, 0.1);
    const Model overridden =
        read_model(dir.write("overridden.yaml", k_base + "  mass_scaling: {time_step: 2.5e-7}\n"),
                   {"control.mass_scaling.time_step=1e-6"});
    EXPECT_EQ(overridden.control.mass_scaling.time_step, 1e-6);
    EXPECT_TRUE(scaled.control.mass_scaling.during_run);
    const Model at_setup = read_model(dir.write(
        "at_setup.yaml", k_base + "  mass_scaling: {time_step: 2.5e-7, during_run: false}\n"));
    EXPECT_FALSE(at_setup.control.mass_scaling.during_run);

    expect_error(k_base + "  rotary_inertia: lsdyna\n", 9, "control.rotary_inertia",
                 "expected one of belytschko, abaqus, radioss");
    expect_error(k_base + "  mass_scaling: {time_step: -1.0e-7}\n", 9,
                 "control.mass_scaling.time_step", "greater than 0");
    expect_error(k_base + "  mass_scaling: {time_step: 0}\n", 9, "control.mass_scaling.time_step",
                 "greater than 0");
    expect_error(k_base + "  mass_scaling: {added_mass_limit: 0.1}\n", 9,
                 "control.mass_scaling.time_step", "is required but missing");
    expect_error(k_base + "  mass_scaling: {time_step: 1.0e-7, added_mass_limit: -0.1}\n", 9,
                 "control.mass_scaling.added_mass_limit", "");
    expect_error(k_base + "  mass_scaling: {time_step: 1.0e-7, dt2ms: 1}\n", 9,
                 "control.mass_scaling.dt2ms", "unknown key");
    expect_error(k_base + "  mass_scaling: 1.0e-7\n", 9, "control.mass_scaling", "expected a map");
    expect_error(k_base + "  mode: relaxation\n  mass_scaling: {time_step: 1.0e-7}\n", 10,
                 "control.mass_scaling", "dynamic runs");
}

// control.minimum_time_step (LS-DYNA's DTMIN and ERODE): a factor or a step, erode or not;
// exactly one of the two, the factor below 1, dynamic runs only.
TEST(ModelReader, ReadsTheMinimumTimeStep) {
    const TempDir dir;
    const Model plain = read_model(dir.write("plain.yaml", k_base));
    EXPECT_FALSE(plain.control.minimum_time_step.active());
    const Model factor =
        read_model(dir.write("factor.yaml", k_base + "  minimum_time_step: {factor: 0.01}\n"));
    EXPECT_EQ(factor.control.minimum_time_step.factor, 0.01);
    EXPECT_FALSE(factor.control.minimum_time_step.erode);
    const Model step = read_model(
        dir.write("step.yaml", k_base + "  minimum_time_step: {time_step: 1.0e-9, erode: true}\n"));
    EXPECT_EQ(step.control.minimum_time_step.time_step, 1e-9);
    EXPECT_TRUE(step.control.minimum_time_step.erode);

    expect_error(k_base + "  minimum_time_step: {factor: 1}\n", 9,
                 "control.minimum_time_step.factor", "below 1");
    expect_error(k_base + "  minimum_time_step: {factor: 0}\n", 9,
                 "control.minimum_time_step.factor", "greater than 0");
    expect_error(k_base + "  minimum_time_step: {factor: 0.1, time_step: 1.0e-9}\n", 9,
                 "control.minimum_time_step", "one of factor");
    expect_error(k_base + "  minimum_time_step: {erode: true}\n", 9, "control.minimum_time_step",
                 "one of factor");
    expect_error(k_base + "  minimum_time_step: {factor: 0.1, erode: yes}\n", 9,
                 "control.minimum_time_step.erode", "expected one of true, false");
    expect_error(k_base + "  mode: relaxation\n  minimum_time_step: {factor: 0.1}\n", 10,
                 "control.minimum_time_step", "dynamic runs");
}

}  // namespace
}  // namespace fpmshell
