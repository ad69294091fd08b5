// Gmsh's C API (gmshc.h) through dlopen; see gmsh_library.hpp for why. gmshc.h only declares
// the functions: decltype gives the type of each pointer looked up, nothing is linked.
#include "fpmshell/mesh/gmsh_library.hpp"

#include <dlfcn.h>
#include <gmshc.h>

#include <memory>

#ifndef FPMSHELL_GMSH_LIBRARY
#define FPMSHELL_GMSH_LIBRARY "libgmsh.so"
#endif

namespace fpmshell {

struct GmshLibrary::Functions {
    decltype(&::gmshFree) free = nullptr;
    decltype(&::gmshInitialize) initialize = nullptr;
    decltype(&::gmshFinalize) finalize = nullptr;
    decltype(&::gmshOptionSetNumber) option_set_number = nullptr;
    decltype(&::gmshOpen) open = nullptr;
    decltype(&::gmshModelMeshGetNodes) get_nodes = nullptr;
    decltype(&::gmshModelMeshGetElements) get_elements = nullptr;
    decltype(&::gmshModelMeshGetElementProperties) get_element_properties = nullptr;
    decltype(&::gmshModelGetPhysicalGroups) get_physical_groups = nullptr;
    decltype(&::gmshModelGetPhysicalName) get_physical_name = nullptr;
    decltype(&::gmshModelGetEntitiesForPhysicalGroup) get_entities_for_physical_group = nullptr;
    decltype(&::gmshModelMeshGetNodesForPhysicalGroup) get_nodes_for_physical_group = nullptr;
    decltype(&::gmshLoggerGetLastError) last_error = nullptr;
};

namespace {

template <class F>
void look_up(void* handle, const char* name, F& out) {
    void* symbol = ::dlsym(handle, name);
    if (!symbol)
        throw GmshError(std::string("the Gmsh library " FPMSHELL_GMSH_LIBRARY " has no function ") +
                        name);
    out = reinterpret_cast<F>(symbol);
}

}  // namespace

GmshLibrary::GmshLibrary() {
    // Never unloaded: Gmsh keeps global state and registers exit handlers.
    void* handle = ::dlopen(FPMSHELL_GMSH_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* why = ::dlerror();
        throw GmshError(std::string("cannot load the Gmsh library (") +
                        (why ? why : FPMSHELL_GMSH_LIBRARY) +
                        "); install the Debian package libgmsh4.8 to read .msh files");
    }
    auto* f = new Functions;  // lives as long as the process, like the library
    look_up(handle, "gmshFree", f->free);
    look_up(handle, "gmshInitialize", f->initialize);
    look_up(handle, "gmshFinalize", f->finalize);
    look_up(handle, "gmshOptionSetNumber", f->option_set_number);
    look_up(handle, "gmshOpen", f->open);
    look_up(handle, "gmshModelMeshGetNodes", f->get_nodes);
    look_up(handle, "gmshModelMeshGetElements", f->get_elements);
    look_up(handle, "gmshModelMeshGetElementProperties", f->get_element_properties);
    look_up(handle, "gmshModelGetPhysicalGroups", f->get_physical_groups);
    look_up(handle, "gmshModelGetPhysicalName", f->get_physical_name);
    look_up(handle, "gmshModelGetEntitiesForPhysicalGroup", f->get_entities_for_physical_group);
    look_up(handle, "gmshModelMeshGetNodesForPhysicalGroup", f->get_nodes_for_physical_group);
    look_up(handle, "gmshLoggerGetLastError", f->last_error);
    f_ = f;
}

const GmshLibrary& GmshLibrary::instance() {
    static const GmshLibrary library;  // a failed load throws and is tried again next time
    return library;
}

namespace {

/// Takes what a Gmsh C function allocated and frees it with gmshFree.
template <class T>
struct GmshArray {
    decltype(&::gmshFree) free;
    T* data = nullptr;
    std::size_t size = 0;
    explicit GmshArray(decltype(&::gmshFree) f) : free(f) {}
    ~GmshArray() {
        if (data) free(data);
    }
    GmshArray(const GmshArray&) = delete;
    GmshArray& operator=(const GmshArray&) = delete;
    [[nodiscard]] std::vector<T> vector() const { return std::vector<T>(data, data + size); }
};

}  // namespace

void GmshLibrary::initialize() const {
    int ierr = 0;
    f_->initialize(0, nullptr, /*readConfigFiles=*/0, &ierr);
    if (ierr != 0) throw GmshError("Gmsh failed to initialise");
}

void GmshLibrary::finalize() const {
    int ierr = 0;
    f_->finalize(&ierr);
}

namespace {

/// Gmsh's last error message, or "<what> failed" when it has none.
std::string last_error(const GmshLibrary::Functions& f, const char* what) {
    char* message = nullptr;
    int ierr = 0;
    f.last_error(&message, &ierr);
    std::string text =
        (ierr == 0 && message && *message) ? std::string(message) : std::string(what) + " failed";
    if (message) f.free(message);
    return text;
}

}  // namespace

void GmshLibrary::set_number_option(const std::string& name, double value) const {
    int ierr = 0;
    f_->option_set_number(name.c_str(), value, &ierr);
    if (ierr != 0) throw GmshError(last_error(*f_, "setting a Gmsh option"));
}

void GmshLibrary::open(const std::string& path) const {
    int ierr = 0;
    f_->open(path.c_str(), &ierr);
    if (ierr != 0) throw GmshError(last_error(*f_, "opening the file"));
}

void GmshLibrary::get_nodes(std::vector<std::size_t>& tags, std::vector<double>& coords) const {
    GmshArray<std::size_t> t(f_->free);
    GmshArray<double> c(f_->free), parametric(f_->free);
    int ierr = 0;
    f_->get_nodes(&t.data, &t.size, &c.data, &c.size, &parametric.data, &parametric.size, -1, -1, 0,
                  0, &ierr);
    if (ierr != 0) throw GmshError(last_error(*f_, "reading the nodes"));
    tags = t.vector();
    coords = c.vector();
}

void GmshLibrary::get_elements(std::vector<int>& types, std::vector<std::vector<std::size_t>>& tags,
                               std::vector<std::vector<std::size_t>>& nodes, int dim,
                               int tag) const {
    GmshArray<int> ty(f_->free);
    std::size_t** tag_lists = nullptr;
    std::size_t* tag_sizes = nullptr;
    std::size_t n_tag_lists = 0;
    std::size_t** node_lists = nullptr;
    std::size_t* node_sizes = nullptr;
    std::size_t n_node_lists = 0;
    int ierr = 0;
    f_->get_elements(&ty.data, &ty.size, &tag_lists, &tag_sizes, &n_tag_lists, &node_lists,
                     &node_sizes, &n_node_lists, dim, tag, &ierr);
    types = ty.vector();
    tags.assign(n_tag_lists, {});
    nodes.assign(n_node_lists, {});
    for (std::size_t k = 0; k < n_tag_lists; ++k) {
        if (ierr == 0) tags[k].assign(tag_lists[k], tag_lists[k] + tag_sizes[k]);
        f_->free(tag_lists[k]);
    }
    for (std::size_t k = 0; k < n_node_lists; ++k) {
        if (ierr == 0) nodes[k].assign(node_lists[k], node_lists[k] + node_sizes[k]);
        f_->free(node_lists[k]);
    }
    for (void* p : {static_cast<void*>(tag_lists), static_cast<void*>(tag_sizes),
                    static_cast<void*>(node_lists), static_cast<void*>(node_sizes)})
        if (p) f_->free(p);
    if (ierr != 0) throw GmshError(last_error(*f_, "reading the elements"));
}

std::string GmshLibrary::element_type_name(int type) const {
    char* name = nullptr;
    int dim = 0, order = 0, n_nodes = 0, n_primary = 0;
    GmshArray<double> local(f_->free);
    int ierr = 0;
    f_->get_element_properties(type, &name, &dim, &order, &n_nodes, &local.data, &local.size,
                               &n_primary, &ierr);
    std::string out = (ierr == 0 && name) ? std::string(name) : std::string("unknown");
    if (name) f_->free(name);
    return out;
}

std::vector<std::pair<int, int>> GmshLibrary::physical_groups() const {
    GmshArray<int> dim_tags(f_->free);
    int ierr = 0;
    f_->get_physical_groups(&dim_tags.data, &dim_tags.size, -1, &ierr);
    if (ierr != 0) throw GmshError(last_error(*f_, "reading the physical groups"));
    std::vector<std::pair<int, int>> out;
    for (std::size_t k = 0; k + 1 < dim_tags.size; k += 2)
        out.emplace_back(dim_tags.data[k], dim_tags.data[k + 1]);
    return out;
}

std::string GmshLibrary::physical_name(int dim, int tag) const {
    char* name = nullptr;
    int ierr = 0;
    f_->get_physical_name(dim, tag, &name, &ierr);
    std::string out = name ? std::string(name) : std::string();
    if (name) f_->free(name);
    if (ierr != 0) throw GmshError(last_error(*f_, "reading a physical name"));
    return out;
}

std::vector<int> GmshLibrary::entities_for_physical_group(int dim, int tag) const {
    GmshArray<int> entities(f_->free);
    int ierr = 0;
    f_->get_entities_for_physical_group(dim, tag, &entities.data, &entities.size, &ierr);
    if (ierr != 0) throw GmshError(last_error(*f_, "reading a physical group"));
    return entities.vector();
}

std::vector<std::size_t> GmshLibrary::nodes_for_physical_group(int dim, int tag) const {
    GmshArray<std::size_t> tags(f_->free);
    GmshArray<double> coords(f_->free);
    int ierr = 0;
    f_->get_nodes_for_physical_group(dim, tag, &tags.data, &tags.size, &coords.data, &coords.size,
                                     &ierr);
    if (ierr != 0) throw GmshError(last_error(*f_, "reading the nodes of a physical group"));
    return tags.vector();
}

}  // namespace fpmshell
