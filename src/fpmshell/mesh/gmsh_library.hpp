// The part of the Gmsh SDK that the .msh reader uses, loaded at run time (dlopen) through
// Gmsh's C API. Linking libgmsh into fpmshell would load its ~85 shared libraries (OpenCASCADE,
// FLTK, X11, OpenGL, image codecs) at the start of every run: about 0.1 s of the dynamic
// loader and static constructors, more than a whole run of a small model, spent even when no
// .msh file is read. Loaded here, it costs that only in the child process that reads a .msh
// file (mesh/gmsh_reader.cpp).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fpmshell {

/// A failure of Gmsh itself (its last error message) or of loading the library.
class GmshError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The Gmsh functions of the reader, with the argument conventions of Gmsh's C++ API
/// (gmsh.h), each throwing GmshError where that one throws.
class GmshLibrary {
public:
    /// The library of this process, loaded on first use; throws GmshError when it cannot be.
    static const GmshLibrary& instance();

    void initialize() const;  ///< gmsh::initialize without configuration files
    void finalize() const;
    void set_number_option(const std::string& name, double value) const;
    void open(const std::string& path) const;
    /// All nodes: their tags and coordinates (x y z per node).
    void get_nodes(std::vector<std::size_t>& tags, std::vector<double>& coords) const;
    /// Elements of dimension dim on entity tag (-1: all), grouped by element type.
    void get_elements(std::vector<int>& types, std::vector<std::vector<std::size_t>>& tags,
                      std::vector<std::vector<std::size_t>>& nodes, int dim, int tag) const;
    [[nodiscard]] std::string element_type_name(int type) const;
    [[nodiscard]] std::vector<std::pair<int, int>> physical_groups() const;  ///< (dim, tag)
    [[nodiscard]] std::string physical_name(int dim, int tag) const;
    [[nodiscard]] std::vector<int> entities_for_physical_group(int dim, int tag) const;
    [[nodiscard]] std::vector<std::size_t> nodes_for_physical_group(int dim, int tag) const;

    GmshLibrary(const GmshLibrary&) = delete;
    GmshLibrary& operator=(const GmshLibrary&) = delete;

    struct Functions;  ///< the pointers looked up (gmsh_library.cpp)

private:
    GmshLibrary();
    const Functions* f_;
};

}  // namespace fpmshell
