// Fuzz target: the mesh reader read_abaqus (mesh/abaqus_reader.hpp) on a file of its format (.inp).
#include <cstdint>
#include <filesystem>

#include "../fuzz_support.hpp"
#include "fpmshell/mesh/abaqus_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace fpmshell;
    const std::filesystem::path path = fuzz::write_scratch_file("mesh.inp", data, size);
    fuzz::expect_only([&] { (void)read_abaqus(path.string()); });
    return 0;
}
