// A triangle mesh with named sets, as produced by the mesh generators and the mesh file readers
// (model-format.md `mesh`). The model reader turns it into the nodes, triangles and sets of Model.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// Plain mesh data. Triangles are counter-clockwise about the surface normal documented by
/// the generator (files: as written in the file). Set members are 0-based, sorted and unique.
struct MeshData {
    std::vector<Vec3> nodes;
    std::vector<std::array<Index, 3>> triangles;
    std::map<std::string, std::vector<Index>> node_sets;
    std::map<std::string, std::vector<Index>> element_sets;
    /// For meshes read from a file: the element number (tag/id) in the file of each triangle,
    /// for messages (both halves of a split quadrangle carry its number). Empty for generators.
    std::vector<std::int64_t> element_tag;
    /// For meshes read from an Abaqus or LS-DYNA file: the node number in the file of each node,
    /// increasing (sets of `node_ids` refer to them). Empty for generators and Gmsh files.
    std::vector<std::int64_t> node_tag;
    /// For LS-DYNA files with solids: the numbers of the nodes inside the parts of solids (on no
    /// outer face, no shell), increasing. A set that names one means the rigid body of its solids,
    /// which its outer faces' particles carry: the member is left out.
    std::vector<std::int64_t> inner_node_tag;
    /// For mesh files: what the reader left out, one sentence each ("FILE:LINE: ..."), which the
    /// model reader passes on to Model::notes.
    std::vector<std::string> notes;
};

}  // namespace fpmshell
