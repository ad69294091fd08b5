// Fuzz target: the restart file (io/restart_archive.hpp, driver/restart_files.hpp) as
// `fpmshell run --resume` reads it for fuzz/models/plate_on_anvil.yaml: the solver's state, the
// output schedule and the states of the history, energy and field files; then two steps from
// the loaded state, where a list that passed the checks but does not fit the model would be
// used (a NaN or a huge number may stop the run: RunFailure, as in a run).
//
// The input is the file without its checksum: the target appends the right one, so that the
// fuzzer reaches the sections behind it (the checksum itself has its own tests). The seed is
// the restart file of a run of the model (fuzz/seed_corpora.py).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "../fuzz_support.hpp"
#include "fpmshell/driver/energy_file.hpp"
#include "fpmshell/driver/field_series.hpp"
#include "fpmshell/driver/history_file.hpp"
#include "fpmshell/driver/output_fields.hpp"
#include "fpmshell/driver/output_observer.hpp"
#include "fpmshell/driver/output_schedule.hpp"
#include "fpmshell/driver/restart_files.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace {

const fpmshell::Model& fuzz_model() {
    static const fpmshell::Model model =
        fpmshell::read_model(FPMSHELL_SOURCE_DIR "/fuzz/models/plate_on_anvil.yaml");
    return model;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
    (void)fuzz_model();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace fpmshell;
    const std::string file =
        RestartWriter::with_checksum(std::string_view(reinterpret_cast<const char*>(data), size));
    const std::filesystem::path path = fuzz::write_scratch_file(
        "restart.bin", reinterpret_cast<const std::uint8_t*>(file.data()), file.size());
    const Model& model = fuzz_model();
    const std::filesystem::path dir = fuzz::scratch_folder();
    fuzz::expect_only<RunFailure>([&] {
        ExplicitSolver solver(model);
        OutputSchedule schedule(model);
        ObserverList results;
        results.add<HistoryFile>(model, dir);
        results.add<EnergyFile>(model, dir);
        results.add<FieldSeries>(model, dir, standard_fields(model), [](const std::string&) {});
        RestartFiles::resume(path, solver, schedule, results);
        for (int k = 0; k < 2; ++k) {
            solver.step(model.control.end_time);
            (void)schedule.row_due(solver.time(), false);
            (void)schedule.frame_due(solver.time(), false);
        }
    });
    return 0;
}
