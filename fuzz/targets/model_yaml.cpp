// Fuzz target: the YAML model file (io/model_reader.hpp) as `fpmshell check` reads it, with the
// mesh files it names. The input is the model file; the mesh files of the repository's examples
// and validation problems are copied next to it at start, so that a model naming one
// (`mesh: {file: mesh_8x8.inp}`) reads it too. Then the summary `check` prints, for models of
// up to k_summarized_elements elements.
#include <cstdint>
#include <filesystem>

#include "../fuzz_support.hpp"
#include "fpmshell/driver/model_summary.hpp"
#include "fpmshell/io/model_reader.hpp"

namespace {
/// The summary sets the solver up (masses, time step, contact), in time linear in the elements:
/// 0.8 s for 383 000 elements in the Release build, 17 s under ASan and UBSan, past the 10 s
/// that counts as a hang. Larger models take the same code paths as small ones; their set-up is
/// left to the solver's tests, the reading of them (which a generator's sizes can make large)
/// is still fuzzed.
constexpr fpmshell::Index k_summarized_elements = 20000;
}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
    namespace fs = std::filesystem;
    for (const char* folder : {"validation", "examples"}) {
        const fs::path root = fs::path(FPMSHELL_SOURCE_DIR) / folder;
        if (!fs::is_directory(root)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(root)) {
            const fs::path ext = entry.path().extension();
            if (entry.is_regular_file() && (ext == ".inp" || ext == ".msh" || ext == ".k"))
                fs::copy_file(entry.path(),
                              fpmshell::fuzz::scratch_folder() / entry.path().filename(),
                              fs::copy_options::overwrite_existing);
        }
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace fpmshell;
    const std::filesystem::path path = fuzz::write_scratch_file("model.yaml", data, size);
    fuzz::expect_only([&] {
        const Model model = read_model(path.string());
        if (model.n_elements() <= k_summarized_elements) (void)model_summary(model);
    });
    return 0;
}
