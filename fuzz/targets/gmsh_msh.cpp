// Fuzz target: the mesh reader read_gmsh (mesh/gmsh_reader.hpp) on a .msh file: the header
// check here, then Gmsh in a child process (a crash or a hang of Gmsh is an InputError), its
// mesh sent back through a pipe and checked.
#include <chrono>
#include <cstdint>
#include <filesystem>

#include "../fuzz_support.hpp"
#include "fpmshell/mesh/gmsh_library.hpp"
#include "fpmshell/mesh/gmsh_reader.hpp"

// The Gmsh library is loaded here, once, so that every child process inherits it: loading it
// (about a hundred shared libraries) would otherwise cost each input ~0.1 s in its child. The
// child still initialises Gmsh, reads the file and finalises Gmsh for every input.
extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
    (void)fpmshell::GmshLibrary::instance();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace fpmshell;
    const std::filesystem::path path = fuzz::write_scratch_file("mesh.msh", data, size);
    fuzz::expect_only([&] { (void)read_gmsh(path.string(), std::chrono::seconds(5)); });
    return 0;
}
