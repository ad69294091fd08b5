// Unit tests of the YAML model reader's errors (io/model_reader.hpp): every error category gives
// one sentence with the file, the line and the key; a mesh file that is not a mesh and malformed
// input give InputErrors, never a crash or a hang; --set overrides apply or are refused.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/model_reader_fixture.hpp"

namespace fpmshell {
namespace {

using test::expect_error;
using test::expect_override_error;
using test::k_base;
using test::replaced;
using test::TempDir;

// Every error category names the file, the line and the key in one sentence.
TEST(ModelReader, EveryErrorNamesFileLineAndKey) {
    struct Case {
        std::string yaml;
        int line;
        std::string key;
        std::string part;
    };
    const std::string plate = "mesh: {generator: plate, length_x: 2, length_y: 1, nx: 4, ny: 2}";
    const std::string steel = "poisson_ratio: 0.3}";
    const std::string section = "  - {elements: all, material: steel, thickness: 0.1}";
    // the base model with its material tabulated and `keys` in place of its poisson_ratio
    auto tabulated = [&](const std::string& keys) {
        return replaced(replaced(k_base, "type: elastic", "type: tabulated"), steel, keys);
    };
    const std::vector<Case> cases = {
        // unknown keys, with a suggestion and the valid keys
        {k_base + "contorl: 1\n", 9, "contorl",
         "unknown key (did you mean 'control'?); valid keys at the top level are title, mesh"},
        {k_base + "  end_tme: 2\n", 9, "control.end_tme", "(did you mean 'end_time'?)"},
        {replaced(k_base, "nx: 4", "nxx: 4"), 2, "mesh.nxx", "valid keys under 'mesh' are"},
        {replaced(k_base, steel, "poisson_ratio: 0.3, colour: red}"), 4, "materials.steel.colour",
         "unknown key"},
        // wrong types, missing keys, scalars where maps or lists are expected
        {replaced(k_base, "end_time: 1.0e-3", "end_time: abc"), 8, "control.end_time",
         "expected a number, got 'abc'"},
        {replaced(k_base, "end_time: 1.0e-3", "end_time: [1, 2]"), 8, "control.end_time",
         "expected a number, got a list"},
        {replaced(k_base, "end_time: 1.0e-3", "mode: dynamic"), 7, "control.end_time",
         "is required but missing"},
        {replaced(k_base, "control:\n  end_time: 1.0e-3", "control: 5"), 7, "control",
         "expected a map"},
        {replaced(k_base, plate, "mesh: 5"), 2, "mesh", "expected a map"},
        {replaced(k_base, section, "  - 5"), 6, "sections.0", "expected a map"},
        {replaced(k_base, "sections:\n" + section, "sections: all"), 5, "sections",
         "expected a list"},
        {replaced(k_base, "sections:\n" + section + "\n", ""), 1, "sections",
         "is required but missing"},
        {replaced(k_base, "control:\n  end_time: 1.0e-3\n",
                  "control:\n  end_time: 1\n  end_time: 2\n"),
         9, "control.end_time", "appears twice"},
        // numbers out of range
        {replaced(k_base, "end_time: 1.0e-3", "end_time: 0"), 8, "control.end_time",
         "greater than 0"},
        {replaced(k_base, "end_time: 1.0e-3", "end_time: -1"), 8, "control.end_time",
         "greater than 0"},
        {replaced(k_base, "end_time: 1.0e-3", "end_time: .nan"), 8, "control.end_time",
         "finite number"},
        {replaced(k_base, "end_time: 1.0e-3", "end_time: .inf"), 8, "control.end_time",
         "finite number"},
        {replaced(k_base, "end_time: 1.0e-3", "end_time: 1e999"), 8, "control.end_time",
         "out of the range"},
        {k_base + "  time_step_scale: 1.5\n", 9, "control.time_step_scale", "(0, 1]"},
        {k_base + "  time_step_scale: 0\n", 9, "control.time_step_scale", "greater than 0"},
        {k_base + "  tolerance: 0\n", 9, "control.tolerance", "greater than 0"},
        {k_base + "  mode: static\n", 9, "control.mode", "expected one of dynamic, relaxation"},
        {k_base + "  bending: dtk\n", 9, "control.bending", "did you mean 'dkt'"},
        {k_base + "  max_relaxation_iterations: 0.5\n", 9, "control.max_relaxation_iterations",
         "whole number"},
        {replaced(k_base, "thickness: 0.1", "thickness: 0"), 6, "sections.0.thickness",
         "greater than 0"},
        {replaced(k_base, "thickness: 0.1", "thickness: -0.1"), 6, "sections.0.thickness",
         "greater than 0"},
        {replaced(k_base, "thickness: 0.1", "thickness: 0.1, thickness_points: 11"), 6,
         "sections.0.thickness_points", "a whole number from 1 to 10"},
        {replaced(k_base, "thickness: 0.1", "thickness: 0.1, inplane_points: 6"), 6,
         "sections.0.inplane_points", "3 or 7"},
        {replaced(k_base, "density: 7.8e-9", "density: 0"), 4, "materials.steel.density",
         "greater than 0"},
        {replaced(k_base, "youngs_modulus: 210000", "youngs_modulus: -1"), 4,
         "materials.steel.youngs_modulus", "greater than 0"},
        {replaced(k_base, "poisson_ratio: 0.3", "poisson_ratio: 0.5"), 4,
         "materials.steel.poisson_ratio", "less than 0.5"},
        {replaced(k_base, "poisson_ratio: 0.3", "poisson_ratio: -1"), 4,
         "materials.steel.poisson_ratio", "greater than -1"},
        {replaced(k_base, ", poisson_ratio: 0.3", ""), 4, "materials.steel.poisson_ratio",
         "is required"},
        {replaced(k_base, "type: elastic", "type: johnson_cook"), 4, "materials.steel.A",
         "is required but missing"},
        {replaced(replaced(k_base, "type: elastic", "type: johnson_cook"), steel,
                  "poisson_ratio: 0.3, A: 300, B: 200, n: 0.3, m: 1}"),
         4, "materials.steel.m", "unknown key"},
        {replaced(replaced(k_base, "type: elastic", "type: johnson_cook"), steel,
                  "poisson_ratio: 0.3, A: 300, B: 200, n: 0.3, thermal_softening: {m: 1, "
                  "room_temperature: 300, melt_temperature: 290, specific_heat: 450}}"),
         4, "materials.steel.thermal_softening.melt_temperature", "must be above room_temperature"},
        {replaced(replaced(k_base, "type: elastic", "type: johnson_cook"), steel,
                  "poisson_ratio: 0.3, A: 300, B: 200, n: 0.3, thermal_softening: {m: 1, "
                  "room_temperature: 300, melt_temperature: 1800, specific_heat: 450, "
                  "taylor_quinney: 1.5}}"),
         4, "materials.steel.thermal_softening.taylor_quinney", "in (0, 1]"},
        // plastic materials
        {replaced(k_base, "type: elastic", "type: j2_plastic"), 4, "materials.steel.yield_stress",
         "is required but missing"},
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 200, tangent_modulus: 3.0e5}"),
         4, "materials.steel.tangent_modulus", "must be below youngs_modulus"},
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 200, hardening_mix: 1.5}"),
         4, "materials.steel.hardening_mix", "must be in [0, 1]"},
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 200, cowper_symonds: {D: 40}}"),
         4, "materials.steel.cowper_symonds.q", "is required but missing"},
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 200, rate_scaling: [[0, 1]]}"),
         4, "materials.steel.rate_scaling", "at least two"},
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 200, rate_scaling: [[0, 1], [0, 1.2]]}"),
         4, "materials.steel.rate_scaling.1.0", "must increase"},
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 200, rate_scaling: [[0, 1.2], [10, 1.1]]}"),
         4, "materials.steel.rate_scaling.1.1", "must not decrease"},
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 200, rate_scaling: [[0, 0], [10, 1.1]]}"),
         4, "materials.steel.rate_scaling.0.1", "greater than 0"},
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 200, cowper_symonds: {D: 40, q: 5}, "
                  "rate_scaling: [[0, 1], [10, 1.1]]}"),
         4, "materials.steel.rate_scaling", "not both"},
        {replaced(k_base, steel, "poisson_ratio: 0.3, cowper_symonds: {D: 6500, q: 4}}"), 4,
         "materials.steel.cowper_symonds", "belongs to plastic materials"},
        // tabulated flow curves
        {replaced(k_base, "type: elastic", "type: tabulated"), 4, "materials.steel.flow_curve",
         "is required but missing"},
        {tabulated("poisson_ratio: 0.3, flow_curve: [[0, 200]]}"), 4, "materials.steel.flow_curve",
         "at least two"},
        {tabulated("poisson_ratio: 0.3, flow_curve: [[0.01, 200], [0.1, 300]]}"), 4,
         "materials.steel.flow_curve.0.0", "must be at plastic strain 0"},
        {tabulated("poisson_ratio: 0.3, flow_curve: [[0, 0], [0.1, 300]]}"), 4,
         "materials.steel.flow_curve.0.1", "must be > 0"},
        {tabulated("poisson_ratio: 0.3, flow_curve: [[0, 200], [0.1, 300], [0.1, 310]]}"), 4,
         "materials.steel.flow_curve.2.0", "must increase strictly, but '0.1' follows '0.1'"},
        {tabulated("poisson_ratio: 0.3, flow_curve: [[0, 200], [0.1, 300], [0.2, 290]]}"), 4,
         "materials.steel.flow_curve.2.1", "softening is not supported"},
        {tabulated("poisson_ratio: 0.3, flow_curve: [[0, 200], [0.1, .nan]]}"), 4,
         "materials.steel.flow_curve.1.1", "finite number"},
        {tabulated("poisson_ratio: 0.3, flow_curve: [[0, 200], 0.1]}"), 4,
         "materials.steel.flow_curve.1", "two numbers [plastic strain, flow stress], got '0.1'"},
        {tabulated("poisson_ratio: 0.3, flow_curve: [[0, 200], [1, 300]], yield_stress: 200}"), 4,
         "materials.steel.yield_stress",
         "belongs to plastic materials (type: j2_plastic or power_law), not to type tabulated"},
        {replaced(k_base, steel, "poisson_ratio: 0.3, flow_curve: [[0, 200], [1, 300]]}"), 4,
         "materials.steel.flow_curve", "belongs to plastic materials"},
        // theory.md §7.7: what a failed element does
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 250, failure: {plastic_strain: 0.2, "
                  "fracture: split}}"),
         4, "materials.steel.failure.fracture", "is 'split'; give erode"},
        // a material's floor of the element step (LS-DYNA's TDEL): > 0, and enough alone
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 250, failure: {minimum_time_step: -1e-7}}"),
         4, "materials.steel.failure.minimum_time_step", "must be greater than 0"},
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 250, failure: {points: 2}}"),
         4, "materials.steel.failure", "names no failure criterion"},
        // the failed layers that erode an element (LS-DYNA's NUMFIP < 0)
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 250, failure: {plastic_strain: 0.2, "
                  "layer_fraction: 1.5}}"),
         4, "materials.steel.failure.layer_fraction", "must be at most 1"},
        {replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                  "poisson_ratio: 0.3, yield_stress: 250, failure: {plastic_strain: 0.2, "
                  "points: 2, layer_fraction: 0.5}}"),
         4, "materials.steel.failure.layer_fraction", "give points or layer_fraction, not both"},
        {tabulated("poisson_ratio: 0.3, flow_curve: [[0, 200], [1, 300]], flow_curves: []}"), 4,
         "materials.steel.flow_curves", "either flow_curve"},
        {tabulated("poisson_ratio: 0.3, flow_curves: [{strain_rate: 10, points: [[0, 200], [1, "
                   "300]]}, {strain_rate: 10, points: [[0, 250], [1, 350]]}]}"),
         4, "materials.steel.flow_curves.1.strain_rate", "must increase, but '10' follows 10"},
        {tabulated("poisson_ratio: 0.3, flow_curves: [{strain_rate: 0, points: [[0, 200], [1, "
                   "300]]}, {strain_rate: 10, points: [[0, 250], [0.5, 260], [1, 280]]}]}"),
         4, "materials.steel.flow_curves.1",
         "lies below the one at strain rate 0 near plastic strain 1; the curves must not cross"},
        {tabulated("poisson_ratio: 0.3, flow_curves: [{strain_rate: 0, points: [[0, 200], [1, "
                   "300]]}, {strain_rate: 10, points: [[0, 250], [1, 350]]}], cowper_symonds: "
                   "{D: 40, q: 5}}"),
         4, "materials.steel.cowper_symonds", "cannot be combined with flow_curves"},
        {tabulated("poisson_ratio: 0.3, flow_curves: [{strain_rate: 0, points: [[0, 200], [1, "
                   "300]]}, {strain_rate: 10, points: [[0, 250], [1, 350]]}], hardening_mix: "
                   "0.5}"),
         4, "materials.steel.hardening_mix", "must be 1 (isotropic) with flow_curves"},
        {tabulated("poisson_ratio: 0.3, flow_curves: [{strain_rate: -1, points: [[0, 200], [1, "
                   "300]]}]}"),
         4, "materials.steel.flow_curves.0.strain_rate", "must be 0 or more, got '-1'"},
        {replaced(k_base, steel, "poisson_ratio: 0.3, yield_stress: 200}"), 4,
         "materials.steel.yield_stress", "belongs to plastic materials"},
        {replaced(replaced(replaced(k_base, "type: elastic", "type: j2_plastic"), steel,
                           "poisson_ratio: 0.3, yield_stress: 200}"),
                  "  end_time: 1.0e-3\n", "  end_time: 1.0e-3\n  mode: relaxation\n"),
         9, "control.mode", "relaxation needs elastic materials"},
        // rigid bodies, contact and the square tube
        {k_base + "rigid_bodies:\n  - {name: striker, point: [0, 0, 1], normal: [0, 0, -1]}\n", 10,
         "rigid_bodies.0.mass", "is required but missing"},
        {k_base + "rigid_bodies:\n  - {name: s, mass: 1, fixed: true, point: [0, 0, 1], normal: "
                  "[0, 0, -1]}\n",
         10, "rigid_bodies.0.mass", "a fixed body has infinite mass"},
        {k_base + "rigid_bodies:\n  - {name: s, mass: 1, point: [0, 0, 1], normal: [0, 0, 0]}\n",
         10, "rigid_bodies.0.normal", "must not be the zero vector"},
        {k_base + "rigid_bodies:\n  - {name: s, mass: 1, shape: cone, point: [0, 0, 1], normal: "
                  "[0, 0, 1]}\n",
         10, "rigid_bodies.0.shape", "expected one of plane"},
        {k_base + "rigid_bodies:\n  - {name: s, mass: 1, shape: sphere, point: [0, 0, 1], normal: "
                  "[0, 0, 1]}\n",
         10, "rigid_bodies.0.normal", "is not a key of a sphere (radius)"},
        {k_base + "rigid_bodies:\n  - {name: s, mass: 1, shape: cylinder, point: [0, 0, 1], axis: "
                  "[0, 0, 0], radius: 1}\n",
         10, "rigid_bodies.0.axis", "must not be the zero vector"},
        {k_base + "rigid_bodies:\n  - {name: s, mass: 1, point: [0, 0, 1], normal: [0, 0, 1], "
                  "edge: [0, 0, 2], size: [1, 1]}\n",
         10, "rigid_bodies.0.edge", "must not be along the normal"},
        {k_base + "contact: [{type: rigid, body: ram}]\n", 9, "contact.0.body",
         "the model has no rigid_bodies"},
        {replaced(k_base, "  end_time: 1.0e-3\n",
                  "  end_time: 1.0e-3\n  end_when_body_stops: ram\n") +
             "rigid_bodies:\n  - {name: striker, mass: 1, point: [0, 0, 1], normal: [0, 0, -1]}\n",
         9, "control.end_when_body_stops", "unknown rigid body 'ram'; the bodies are striker"},
        {replaced(k_base, "  end_time: 1.0e-3\n",
                  "  end_time: 1.0e-3\n  end_when_body_stops: w\n") +
             "rigid_bodies:\n  - {name: w, fixed: true, point: [0, 0, 1], normal: [0, 0, -1], "
             "velocity: [0, 0, -1]}\n",
         9, "control.end_when_body_stops", "is fixed: it keeps its velocity and never stops"},
        {replaced(k_base, "  end_time: 1.0e-3\n",
                  "  end_time: 1.0e-3\n  end_when_body_stops: w\n") +
             "rigid_bodies:\n  - {name: w, mass: 1, point: [0, 0, 1], normal: [0, 0, -1]}\n",
         9, "control.end_when_body_stops", "has no initial velocity"},
        {k_base + "contact: [{type: sliding}]\n", 9, "contact.0.type",
         "expected one of self, rigid"},
        {k_base + "contact: [{type: self, method: lagrangian}]\n", 9, "contact.0.method",
         "expected one of lagrange, penalty, got 'lagrangian'"},
        {k_base + "contact: [{type: self, method: penalty, penalty_scale: 2}]\n", 9,
         "contact.0.penalty_scale", "must be in (0, 1]"},
        {k_base + "rigid_bodies:\n  - {name: w, mass: 1, point: [0, 0, 1], normal: [0, 0, 1]}\n"
                  "contact:\n  - {type: rigid, body: w}\n",
         12, "contact.0", "starts 1.050000 inside the face of rigid body 'w'"},
        {k_base + "rigid_bodies:\n  - {name: w, mass: 1, point: [0, 0, 1], normal: [0, 0, -1]}\n"
                  "contact:\n  - {type: rigid, body: w, friction: -0.1}\n",
         12, "contact.0.friction", "must be 0 or more, got '-0.1'"},
        {k_base + "rigid_bodies:\n  - {name: w, mass: 1, point: [0, 0, 1], normal: [0, 0, -1]}\n"
                  "contact:\n  - {type: rigid, body: w, friction: sticky}\n",
         12, "contact.0.friction", "expected a number, got 'sticky'"},
        {k_base + "output:\n  histories:\n    - {name: s, quantity: rigid_striker_uz}\n", 11,
         "output.histories.0.quantity", "the model has no rigid_bodies"},
        {k_base + "rigid_bodies:\n  - {name: w, mass: 1, point: [0, 0, 1], normal: [0, 0, -1]}\n"
                  "output:\n  histories:\n    - {name: s, quantity: rigid_w_uq}\n",
         13, "output.histories.0.quantity", "unknown rigid-body quantity 'uq' of body 'w'"},
        {k_base + "rigid_bodies:\n  - {name: w, mass: 1, point: [0, 0, 1], normal: [0, 0, -1]}\n"
                  "output:\n  histories:\n    - {name: s, nodes: all, quantity: rigid_w_uz}\n",
         13, "output.histories.0.nodes", "belongs to the body"},
        {replaced(k_base, plate, "mesh: {generator: square_tube, width: 1, length: 2}"), 2,
         "mesh.divisions_width", "is required but missing"},
        {replaced(k_base, plate,
                  "mesh: {generator: square_tube, width: 1, length: 2, divisions_width: 2, "
                  "divisions_length: 4, sector_deg: 180}"),
         2, "mesh.sector_deg", "expected 90"},
        {replaced(k_base, "  end_time: 1.0e-3\n", "  end_time: 1.0e-3\n  mode: relaxation\n") +
             "contact: [{type: self}]\n",
         10, "contact", "contact needs mode: dynamic"},
        // unknown names of sets, materials and curves
        {replaced(k_base, "material: steel", "material: stel"), 6, "sections.0.material",
         "unknown material 'stel' (did you mean 'steel'?)"},
        {replaced(k_base, "elements: all", "elements: al"), 6, "sections.0.elements",
         "unknown element set 'al'"},
        {replaced(k_base, "elements: all", "elements: xmin"), 6, "sections.0.elements",
         "'xmin' is a node set, not an element set"},
        {k_base + "boundary:\n  - {nodes: rim, fix: all}\n", 10, "boundary.0.nodes",
         "unknown node set 'rim'; the model defines the node sets all, boundary, xmax"},
        {k_base + "loads:\n  - {type: force, nodes: all, value: [0, 0, 1], curve: stp}\ncurves:\n  "
                  "step: [[0, 1]]\n",
         10, "loads.0.curve", "unknown curve 'stp' (did you mean 'step'?)"},
        {k_base + "loads:\n  - {type: force, nodes: all, value: [0, 0, 1], curve: c}\n", 10,
         "loads.0.curve", "defines no curves"},
        // boundary, curves, loads, initial conditions, damping
        {k_base + "boundary:\n  - {nodes: all}\n", 10, "boundary.0",
         "at least one of fix, symmetry or prescribe"},
        {k_base + "boundary:\n  - {nodes: all, fix: [ux, uw]}\n", 10, "boundary.0.fix.1",
         "expected one of ux, uy, uz, rx, ry, rz"},
        {k_base + "boundary:\n  - {nodes: all, fix: some}\n", 10, "boundary.0.fix",
         "expected one of all"},
        {k_base + "boundary:\n  - {nodes: all, symmetry: w}\n", 10, "boundary.0.symmetry",
         "expected one of x, y, z"},
        {k_base + "boundary:\n  - {nodes: all, prescribe: {velocity: [1, 0, 0], displacement: [0, "
                  "0, 1]}}\n",
         10, "boundary.0.prescribe",
         "exactly one of displacement, velocity, acceleration or angular_velocity"},
        {k_base + "boundary:\n  - {nodes: all, prescribe: {velocity: [1, 0]}}\n", 10,
         "boundary.0.prescribe.velocity", "3 numbers"},
        {k_base + "curves:\n  c: [[0, 0], [1, 1], [1, 2]]\n", 10, "curves.c.2.0",
         "increase strictly"},
        {k_base + "curves:\n  c: [[0, 0], [1]]\n", 10, "curves.c.1", "pair [time, factor]"},
        {k_base + "curves:\n  c: []\n", 10, "curves.c", "at least one"},
        {k_base + "loads:\n  - {type: pressure, nodes: all, value: 1}\n", 10, "loads.0.nodes",
         "use `elements: SET`"},
        {k_base + "loads:\n  - {type: pressure, elements: all, value: [1, 2, 3]}\n", 10,
         "loads.0.value", "expected a number"},
        {k_base + "loads:\n  - {type: force, nodes: all, value: 5}\n", 10, "loads.0.value",
         "3 numbers"},
        {k_base + "loads:\n  - {type: heat, nodes: all, value: 5}\n", 10, "loads.0.type",
         "expected one of pressure, force, moment, gravity"},
        {k_base + "loads:\n  - {type: gravity, nodes: all, value: [0, 0, -9.81]}\n", 10,
         "loads.0.nodes", "use `elements: SET`"},
        {k_base + "loads:\n  - {type: gravity, value: -9.81}\n", 10, "loads.0.value", "3 numbers"},
        {k_base + "initial_conditions:\n  - {nodes: all}\n", 10, "initial_conditions.0",
         "velocity"},
        {k_base + "damping: {mass: -1}\n", 9, "damping.mass", "0 or more"},
        // output histories
        {k_base + "output:\n  histories:\n    - {name: w, nodes: xmin, quantity: uz}\n", 11,
         "output.histories.0.nodes", "needs `reduce: sum`"},
        {k_base + "output:\n  histories:\n    - {name: w, nodes: all, quantity: uz, reduce: max}\n "
                  "   - {name: w, nodes: all, quantity: ux, reduce: max}\n",
         12, "output.histories.1.name", "used twice"},
        {k_base +
             "output:\n  histories:\n    - {name: 'a,b', nodes: all, quantity: uz, reduce: max}\n",
         11, "output.histories.0.name", "commas"},
        {k_base +
             "output:\n  histories:\n    - {name: '', nodes: all, quantity: uz, reduce: max}\n",
         11, "output.histories.0.name", "empty"},
        {k_base +
             "output:\n  histories:\n    - {name: time, nodes: all, quantity: uz, reduce: max}\n",
         11, "output.histories.0.name", "first column"},
        {k_base +
             "output:\n  histories:\n    - {name: w, nodes: all, quantity: uzz, reduce: max}\n",
         11, "output.histories.0.quantity", "did you mean 'uz'"},
        {k_base + "output:\n  histories:\n    - {name: w, nodes: all, quantity: uz, reduce: avg}\n",
         11, "output.histories.0.reduce", "sum, max, min, mean"},
        {k_base + "output: {every: -1}\n", 9, "output.every", "0 or more"},
        // sets
        {k_base + "sets:\n  far: {near: [9, 9, 9], tolerance: 0.1}\n", 10, "sets.far",
         "the set is empty"},
        {k_base + "sets:\n  xmin: {near: [0, 0, 0]}\n", 10, "sets.xmin",
         "already defined by the mesh"},
        {k_base + "sets:\n  all: {near: [0, 0, 0]}\n", 10, "sets.all", "reserved"},
        {k_base + "sets:\n  s: {near: [0, 0, 0], box: [[0, 0, 0], [1, 1, 1]]}\n", 10, "sets.s",
         "exactly one of near"},
        {k_base + "sets:\n  s: {box: [[1, 0, 0], [0, 1, 1]]}\n", 10, "sets.s.box",
         "the first corner must be the minimum"},
        {k_base + "sets:\n  s: {plane: {point: [0, 0, 0], normal: [0, 0, 0]}}\n", 10,
         "sets.s.plane.normal", "zero vector"},
        {k_base + "sets:\n  s: {plane: {point: [0, 0, 0]}}\n", 10, "sets.s.plane.normal",
         "is required"},
        {k_base +
             "sets:\n  s: {near: [0, 0, 0]}\nloads:\n  - {type: pressure, elements: s, value: 1}\n",
         12, "loads.0.elements", "contains no element"},
        // sections must cover every element
        {replaced(k_base, "elements: all", "elements: half") +
             "sets:\n  half: {box: [[0, 0, -1], [1, 1, 1]]}\n",
         5, "sections", "has no section"},
        // mesh generators
        {replaced(k_base, "nx: 4", "nx: -3"), 2, "mesh.nx", "whole number from 1"},
        {replaced(k_base, "nx: 4", "nx: 2.5"), 2, "mesh.nx", "whole number"},
        {replaced(k_base, "nx: 4", "nx: many"), 2, "mesh.nx", "whole number"},
        {replaced(k_base, "nx: 4, ny: 2", "nx: 1e7, ny: 1e7"), 2, "mesh", "more than the limit"},
        {replaced(k_base, "nx: 4", "nx: 1e30"), 2, "mesh.nx", "whole number"},
        {replaced(k_base, "length_x: 2", "length_x: 0"), 2, "mesh.length_x", "greater than 0"},
        {replaced(k_base, ", ny: 2", ""), 2, "mesh.ny", "is required"},
        {replaced(k_base, "generator: plate", "generator: plat"), 2, "mesh.generator",
         "did you mean 'plate'"},
        {replaced(k_base, plate, "mesh: {generator: plate, file: a.msh}"), 2, "mesh",
         "keep exactly one"},
        {replaced(k_base, plate, "mesh: {nx: 3}"), 2, "mesh", "needs either `generator` or `file`"},
        {replaced(k_base, "nx: 4", "nx: 4, pattern: diagonal"), 2, "mesh.pattern",
         "right, left, alternate, cross"},
        {replaced(k_base, plate,
                  "mesh: {generator: spherical_cap, radius: 1, half_angle_deg: 30, sector_deg: 45, "
                  "divisions: 3}"),
         2, "mesh.sector_deg", "multiple of 60"},
        {replaced(k_base, plate,
                  "mesh: {generator: spherical_cap, radius: 1, half_angle_deg: 180, divisions: 3}"),
         2, "mesh.half_angle_deg", "less than 180"},
        {replaced(k_base, plate,
                  "mesh: {generator: cylinder_panel, radius: 1, length: 1, angle_deg: 400, "
                  "divisions_arc: 3, divisions_length: 1}"),
         2, "mesh.angle_deg", "at most 360"},
        {replaced(k_base, plate,
                  "mesh: {generator: cylinder_panel, radius: 1, length: 1, angle_deg: 360, "
                  "divisions_arc: 2, divisions_length: 1}"),
         2, "mesh.divisions_arc", "from 3"},
        {replaced(k_base, plate,
                  "mesh: {generator: annulus, inner_radius: 2, outer_radius: 1, divisions_radial: "
                  "1, divisions_angle: 4}"),
         2, "mesh.outer_radius", "greater than inner_radius"},
        {replaced(k_base, plate, "mesh: {file: nothere.msh}"), 2, "mesh.file", "does not exist"},
        {replaced(k_base, plate, "mesh: {file: .}"), 2, "mesh.file", "not a regular file"},
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        SCOPED_TRACE("case " + std::to_string(i) + ": " + cases[i].key);
        expect_error(cases[i].yaml, cases[i].line, cases[i].key, cases[i].part);
    }
}

// A mesh file of an unknown type, or one that is not a usable mesh, is refused with the key
// mesh.file and the reason found in the mesh file.
TEST(ModelReader, RefusesMeshFilesThatAreNotMeshes) {
    const TempDir dir;
    (void)dir.write("plate.inp", "*NODE\n1, 0, 0, 0\n");
    (void)dir.write("plate.stl", "solid x\n");
    (void)dir.write("fake.msh", "Point(1) = {0, 0, 0};\n");
    const std::string plate = "mesh: {generator: plate, length_x: 2, length_y: 1, nx: 4, ny: 2}";
    expect_error(replaced(k_base, plate, "mesh: {file: " + dir.path("plate.inp") + "}"), 2,
                 "mesh.file", "plate.inp: the file holds no shell element");
    expect_error(replaced(k_base, plate, "mesh: {file: " + dir.path("plate.stl") + "}"), 2,
                 "mesh.file", "unknown mesh file type '.stl'");
    expect_error(replaced(k_base, plate, "mesh: {file: " + dir.path("fake.msh") + "}"), 2,
                 "mesh.file", "not a Gmsh mesh file");
}

// Problems with the file itself: missing, a folder, empty, YAML syntax errors (with their
// line), a list or a scalar at the top level, binary garbage, runaway nesting and cyclic
// aliases all give an InputError and never a crash or a hang.
TEST(ModelReader, MalformedFilesGiveInputErrors) {
    {
        const TempDir dir;
        const std::string missing = dir.path("missing.yaml");
        try {
            (void)read_model(missing);
            ADD_FAILURE() << "no error for a missing file";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(missing + ": cannot open", 0), 0U) << e.what();
        }
        EXPECT_THROW((void)read_model(dir.path("")), InputError);  // a folder
    }
    expect_error("", 0, "", "empty");
    expect_error("# only a comment\n", 0, "", "empty");
    expect_error("title: x\nmesh: [1, 2\n", 3, "", "not valid YAML");
    expect_error("title: x\n  bad indentation: 1\n", 2, "", "not valid YAML");
    expect_error("- 1\n- 2\n", 1, "", "must be a map");
    expect_error("hello\n", 1, "", "must be a map");
    constexpr char binary[] = "\0\x01\xff\xfe garbage \x80";  // with a NUL inside
    expect_error(std::string(binary, sizeof binary - 1), -1, "", "");
    expect_error(std::string(20000, '['), -1, "", "");
    expect_error(k_base + "damping: &d {mass: *d}\n", 9, "damping.mass", "expected a number");
    expect_error(replaced(k_base, "control:\n  end_time: 1.0e-3\n", ""), 1, "control",
                 "is required but missing");
    expect_error(k_base + "? [a, b]\n: 1\n", 9, "", "plain names");
}

// --set overrides replace scalars and vectors by key path (list items by index) before the
// model is read; bad paths, maps and malformed overrides are refused naming "--set" and the key.
TEST(ModelReader, AppliesSetOverrides) {
    const TempDir dir;
    const std::string file =
        dir.write("model.yaml", k_base +
                                    "loads:\n  - {type: pressure, elements: all, value: 600}\n"
                                    "  - {type: force, nodes: all, value: [0, 0, -1]}\n");
    const Model m = read_model(
        file, {"control.end_time=2e-3", "loads.0.value=700", "loads.1.value=[0, 0, -3]",
               "mesh.nx=8", "materials.steel.poisson_ratio = 0.25", "control.end_time=4e-3"});
    EXPECT_EQ(m.control.end_time, 4e-3);  // the later override wins
    EXPECT_EQ(m.loads[0].pressure, 700.0);
    EXPECT_EQ(m.loads[1].vector, Vec3(0, 0, -3));
    EXPECT_EQ(m.n_particles(), 9 * 3);
    EXPECT_EQ(m.materials[0].poisson_ratio, 0.25);
    EXPECT_DOUBLE_EQ(m.output.every, 4e-3 / 200);  // defaults follow the overridden end_time

    expect_override_error({"control.end_time=-1"}, "control.end_time", "greater than 0");
    expect_override_error({"control.end_time=abc"}, "control.end_time", "expected a number");
    expect_override_error({"control.time_step_scale=0.5"}, "control.time_step_scale",
                          "does not exist");
    expect_override_error({"sections.3.thickness=1"}, "sections.3.thickness", "does not exist");
    expect_override_error({"sections.x.thickness=1"}, "sections.x.thickness", "does not exist");
    expect_override_error({"control=1"}, "control", "holds a map");
    expect_override_error({"sections=1"}, "sections", "holds a map or a list of lists or maps");
    expect_override_error({"control.end_time"}, "control.end_time", "key.path=value");
    expect_override_error({"control.end_time="}, "control.end_time", "no value");
    expect_override_error({"control.end_time=[1"}, "control.end_time", "not valid YAML");
    expect_override_error({"control..end_time=1"}, "control..end_time", "empty component");
    expect_override_error({"mesh.nx=0"}, "mesh.nx", "whole number");
}

}  // namespace
}  // namespace fpmshell
