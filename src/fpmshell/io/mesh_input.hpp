// The `mesh` block of the model file (model-format.md): a generator with its parameters, or a
// mesh file, followed by the checks every mesh must pass.
#pragma once

#include <string>

#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/mesh/mesh_data.hpp"

namespace fpmshell {

/// Largest mesh accepted (triangles); bigger requests are refused before any allocation.
/// Fuzz builds (cmake/sanitizers.cmake) lower it: a generated mesh of millions of elements is
/// read correctly but takes minutes under the sanitizers, which the fuzzer would report as a hang.
#ifndef FPMSHELL_MAX_MESH_ELEMENTS
#define FPMSHELL_MAX_MESH_ELEMENTS 20.0e6
#endif
inline constexpr double k_max_mesh_elements = FPMSHELL_MAX_MESH_ELEMENTS;

/// Builds the mesh of `mesh: {generator: ...}` or `mesh: {file: ...}`. A relative file path is
/// taken relative to `base_dir` (the folder of the model file). Validates every generator key
/// (positive sizes, divisions >= 1, angles in range), the mesh size, and the mesh itself
/// (check_mesh). Throws InputError naming the key.
[[nodiscard]] MeshData read_mesh_block(const YamlValue& mesh, const std::string& base_dir);

/// Refuses a mesh without triangles, with non-finite coordinates, with node indices out of
/// range, or with a degenerate triangle (area below 1e-12 x the squared longest edge); the
/// message names the element (1-based, and its number in the mesh file when there is one).
void check_mesh(const MeshData& mesh, const YamlValue& mesh_key);

}  // namespace fpmshell
