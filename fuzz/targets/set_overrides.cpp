// Fuzz target: the `--set` overrides (io/overrides.hpp) on a fixed model, as `fpmshell check
// MODEL --set A --set B ...` applies them to fuzz/models/plate_on_anvil.yaml. Each line of the
// input is one override.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "../fuzz_support.hpp"
#include "fpmshell/io/model_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace fpmshell;
    std::vector<std::string> overrides;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        overrides.emplace_back(text.substr(0, end));
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    }
    fuzz::expect_only([&] {
        (void)read_model(FPMSHELL_SOURCE_DIR "/fuzz/models/plate_on_anvil.yaml", overrides);
    });
    return 0;
}
