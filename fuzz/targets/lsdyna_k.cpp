// Fuzz target: the mesh reader read_lsdyna (mesh/lsdyna_reader.hpp) on a file of its format (.k).
#include <cstdint>
#include <filesystem>

#include "../fuzz_support.hpp"
#include "fpmshell/mesh/lsdyna_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace fpmshell;
    const std::filesystem::path path = fuzz::write_scratch_file("mesh.k", data, size);
    fuzz::expect_only([&] { (void)read_lsdyna(path.string()); });
    return 0;
}
