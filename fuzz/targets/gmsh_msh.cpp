// Fuzz target: the mesh reader read_gmsh (mesh/gmsh_reader.hpp) on a .msh file: the header
// check here, then Gmsh in a child process (a crash or a hang of Gmsh is an InputError), its
// mesh sent back through a pipe and checked.
#include <chrono>
#include <cstdint>
#include <filesystem>

#include "../fuzz_support.hpp"
#include "fpmshell/mesh/gmsh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace fpmshell;
    const std::filesystem::path path = fuzz::write_scratch_file("mesh.msh", data, size);
    fuzz::expect_only([&] { (void)read_gmsh(path.string(), std::chrono::seconds(5)); });
    return 0;
}
