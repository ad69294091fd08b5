// Reader of Gmsh .msh meshes through the Gmsh SDK (model-format.md `mesh: {file: x.msh}`).
#pragma once

#include <chrono>
#include <string>

#include "fpmshell/mesh/mesh_data.hpp"

namespace fpmshell {

/// Reads the 3-node triangles (type 2) and 4-node quadrangles (type 3) of a Gmsh .msh file
/// (format 2 or 4, ASCII or binary). Each quadrangle is split along its shorter diagonal into
/// two triangles that keep its orientation. Nodes are renumbered 0..n-1 in increasing Gmsh tag
/// order, keeping only the nodes of the surface elements. Physical groups become sets named by
/// their physical name ("physical_<tag>" when unnamed): a group of dimension 2 gives an element
/// set and a node set (the nodes of its elements), groups of dimension 1 and 0 give node sets.
/// Groups of different dimensions with the same name are merged (their node sets are united).
/// Nodes of a dimension-0/1 group that no surface element uses are dropped; a group left empty
/// gives no set. Throws InputError (naming `path`) when the file cannot be read, is not a .msh
/// file, holds other surface element types, or holds no triangle. Gmsh is initialised and
/// finalised inside the call (also on error), without reading its configuration files.
/// The read runs in a child process: a Gmsh crash, a read longer than time_limit (a hung Gmsh)
/// or one that needs more memory than a mesh of the file's size can (256 MB + 64 bytes per byte
/// of file) is an InputError too.
[[nodiscard]] MeshData read_gmsh(const std::string& path,
                                 std::chrono::seconds time_limit = std::chrono::minutes(10));

}  // namespace fpmshell
