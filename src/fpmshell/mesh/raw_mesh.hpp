// Mesh data as read from a text mesh file (Abaqus .inp, LS-DYNA .k), still with the file's own
// node and element numbers; finish_raw_mesh turns it into a MeshData with compact indices.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/mesh/mesh_data.hpp"

namespace fpmshell {

/// Node, element and set definitions by file id. Sets may name ids of elements that are not
/// shells (line elements): their nodes then go to the node set of the same name.
struct RawMesh {
    struct Node {
        Vec3 x = Vec3::Zero();
        int line = 0;
    };
    struct Element {
        long long id = 0;
        std::vector<long long> nodes;  ///< 3 (triangle) or 4 (quadrangle) node ids
        int line = 0;
    };

    std::string path;  ///< the mesh file, for messages
    std::unordered_map<long long, Node> nodes;
    std::vector<Element> shells;
    std::unordered_map<long long, std::vector<long long>> other_elements;  ///< id -> node ids
    std::map<std::string, std::vector<long long>> node_sets;               ///< name -> node ids
    std::map<std::string, std::vector<long long>> element_sets;            ///< name -> element ids
    std::map<std::string, int> set_lines;                                  ///< name -> first line
    /// name -> the file of that line, where a set may stand in an included file (else `path`)
    std::map<std::string, std::string> set_files;
    /// nodes that carry a point mass (LS-DYNA's *ELEMENT_MASS): particles whether or not a
    /// shell uses them
    std::vector<long long> mass_nodes;
    std::uintmax_t file_bytes = 0;  ///< the size of the file (bounds what GENERATE may list)
    long long generated = 0;        ///< the members listed by GENERATE ranges so far

    /// Adds a node; a second definition of the same id is an InputError.
    void add_node(long long id, const Vec3& x, int line);
    /// Adds a 3- or 4-node shell element (duplicate ids are reported by finish_raw_mesh).
    void add_shell(long long id, std::vector<long long> node_ids, int line);
    /// Counts the `count` members of a GENERATE range on `line` before they are stored. Every
    /// member must be a node or element the file defines, each on a line of its own, so ranges
    /// that list more ids in all than the file has bytes are refused (an absurd range in a small
    /// file would otherwise ask for any amount of memory).
    void add_generated(long long count, int line);
    /// Throws InputError "PATH:LINE: message".
    [[noreturn]] void fail(int line, const std::string& message) const;
    /// The file and first line of set `name`, for messages.
    [[nodiscard]] std::pair<std::string, int> set_place(const std::string& name) const;
    /// fail() at the place of set `name`.
    [[noreturn]] void fail_in_set(const std::string& name, const std::string& message) const;
};

/// Compacts the raw mesh: nodes used by shells, renumbered 0..n-1 in increasing id order;
/// quadrangles split along their shorter diagonal (keeping their orientation); sets mapped to
/// indices. An element set of shells gives an element set and a node set (its nodes); a set
/// of other elements gives a node set; members that are not shells nor nodes of shells are
/// dropped, and a set left empty is dropped. Throws InputError for an element that refers to an
/// undefined node, a set member that is not defined at all, or a file without shells.
[[nodiscard]] MeshData finish_raw_mesh(const RawMesh& raw);

/// Helpers shared by the text readers.
namespace text_mesh {
/// Upper-case copy.
[[nodiscard]] std::string upper(std::string s);
/// Splits at commas, trimming each field (an empty line gives no field).
[[nodiscard]] std::vector<std::string> split_commas(const std::string& s);
/// Splits at blanks.
[[nodiscard]] std::vector<std::string> split_blanks(const std::string& s);
/// Parses a whole integer field; false when it is not one.
[[nodiscard]] bool parse_id(const std::string& field, long long& value);
/// Parses a real field (also Fortran exponents 1.0D+3, and 2.0-3 without the letter); false when
/// it is not a finite number.
[[nodiscard]] bool parse_real(const std::string& field, Real& value);
/// A whole number, also written as a real ("7.0000000", as some writers save an integer field).
[[nodiscard]] bool parse_whole(const std::string& field, long long& value);
}  // namespace text_mesh

}  // namespace fpmshell
