// The readers of the top-level blocks of the model file (model-format.md), one function per
// key; each checks its own keys, types and ranges and adds what it reads to the Model.
// read_model (model_reader.cpp) calls them in the order in which the blocks depend on each
// other: control, mesh and sets, materials, curves, sections, boundary, loads, initial
// conditions, rigid bodies, contact, damping, output.
#pragma once

#include <array>
#include <optional>

#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

// Run control and output (model_control_blocks.cpp).

/// `control`, but for end_when_body_stops, which names a rigid body (read_end_when_body_stops).
void read_control(const YamlValue& v, Model& model);
/// control.end_when_body_stops of the `control` block v, once the rigid bodies are known: a
/// moving body with a velocity, in a dynamic run.
void read_end_when_body_stops(const YamlValue& v, Model& model);
void read_damping(const YamlValue& v, Model& model);
/// `output` (v absent: the default cadences, from control.end_time).
void read_output(const std::optional<YamlValue>& v, Model& model);

// Materials and sections (model_material_blocks.cpp).

void read_materials(const YamlValue& v, Model& model);
/// `sections`, after the mesh sets and the materials: every element must end up with one.
void read_sections(const YamlValue& v, Model& model);

// Curves, boundary conditions, loads and initial conditions (model_condition_blocks.cpp).

void read_curves(const YamlValue& v, Model& model);
/// A `fix` value: `all`, or a non-empty list of ux, uy, uz, rx, ry, rz (true where fixed).
[[nodiscard]] std::array<bool, 6> fixed_dofs(const YamlValue& fix);
void read_boundary(const YamlValue& v, Model& model);
void read_loads(const YamlValue& v, Model& model);
void read_initial_conditions(const YamlValue& v, Model& model);
// Masses lumped on particles (model_point_masses.cpp).

/// `masses`: point masses on node sets and masses spread on element sets by area (LS-DYNA's
/// *ELEMENT_MASS, _NODE_SET, _PART), after the sections.
void read_point_masses(const YamlValue& v, Model& model);
/// The sections' `area_mass` as point masses, after the sections.
void add_area_masses(Model& model);
/// `moves`: node sets translated before the run (LS-DYNA's *PART_MOVE), in their order.
void read_moves(const YamlValue& v, Model& model);
/// `constraints`, after `boundary` (a particle of a nodal rigid body takes no boundary
/// condition).
void read_constraints(const YamlValue& v, Model& model);

// Rigid bodies and contact (model_contact_blocks.cpp).

void read_rigid_bodies(const YamlValue& v, Model& model);
/// `contact`, after the sections (a rigid contact checks the particles' half thickness
/// against the face).
void read_contact(const YamlValue& v, Model& model);

}  // namespace fpmshell
