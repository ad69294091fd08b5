// Fuzz target: the mesh reader read_lsdyna (mesh/lsdyna_reader.hpp) and the deck translator
// translate_lsdyna_deck (io/lsdyna_deck.hpp) on a file of their format (.k).
#include <cstdint>
#include <filesystem>

#include "../fuzz_support.hpp"
#include "fpmshell/io/lsdyna_deck.hpp"
#include "fpmshell/mesh/lsdyna_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace fpmshell;
    const std::filesystem::path path = fuzz::write_scratch_file("mesh.k", data, size);
    fuzz::expect_only([&] { (void)read_lsdyna(path.string()); });
    fuzz::expect_only([&] { (void)translate_lsdyna_deck(path.string(), "mesh.k"); });
    return 0;
}
