// Reader of Abaqus input files (.inp) for shell meshes (model-format.md `mesh: {file: x.inp}`).
#pragma once

#include <string>

#include "fpmshell/mesh/mesh_data.hpp"

namespace fpmshell {

/// Reads *NODE (id, x, y[, z]; optional NSET=), *ELEMENT with a 3-node type (S3, S3R, S3RS,
/// CPS3, CPE3, M3D3, R3D3, STRI3, SFM3D3) or a 4-node type (S4, S4R, S4RS, S4R5, CPS4, CPS4R,
/// CPE4, CPE4R, M3D4, M3D4R, R3D4, SFM3D4, SFM3D4R) and optional ELSET=, *NSET and *ELSET
/// (ids, names of other sets, or GENERATE first, last[, step]). Line elements (T2D*, T3D*, B2*,
/// B3*, ...) are not part of the surface, but their element sets become node sets. Every other
/// keyword is skipped with its data lines; *INCLUDE and other element types are refused.
/// Keywords and parameter names are case-insensitive; set names keep their spelling. An element
/// set gives an element set and a node set of the same name (see finish_raw_mesh).
/// Quadrangles are split into two triangles. Throws InputError "PATH:LINE: ..." on error.
[[nodiscard]] MeshData read_abaqus(const std::string& path);

}  // namespace fpmshell
