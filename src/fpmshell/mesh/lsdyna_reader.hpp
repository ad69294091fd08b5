// Reader of LS-DYNA keyword files (.k, .key, .dyn) for shell meshes.
#pragma once

#include <string>

#include "fpmshell/mesh/mesh_data.hpp"

namespace fpmshell {

/// Reads *NODE, *ELEMENT_SHELL (also _THICKNESS, _BETA, _MCID, _OFFSET: the extra cards are
/// skipped), *SET_NODE_LIST, *SET_SHELL_LIST and *SET_PART_LIST (also _TITLE and _GENERATE
/// variants), through *INCLUDE files (mesh/keyword_deck.hpp). Cards are fixed-width (standard,
/// '+' long or '%' wide-id format) or comma-separated; a card that does not parse in columns
/// is also tried split at blanks. Shells with n3 = n4 are triangles, the others quadrangles
/// (split into two triangles). Sets are named by their title (_TITLE variants), else
/// lsdyna_set_name; every part gives the element and node set "part_<PID>", a part set the
/// element and node set of its parts' elements. Every other keyword is skipped.
/// Throws InputError "PATH:LINE: ..." on error.
[[nodiscard]] MeshData read_lsdyna(const std::string& path);

/// The name of an untitled set: "<kind>_set_<SID>" for `kind` node, shell, part (or segment:
/// the deck translator's sets of segments).
[[nodiscard]] std::string lsdyna_set_name(const std::string& kind, long long sid);

}  // namespace fpmshell
