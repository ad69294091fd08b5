// Runs a validated model and writes every result file of model-format.md ("fpmshell run").
// The solver is driven here and the result files observe it (output_observer.hpp); neither
// knows the other.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fpmshell/driver/model_summary.hpp"
#include "fpmshell/driver/output_observer.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct RunOptions {
    std::filesystem::path output_dir;
    int threads = 0;         ///< 0 = all available
    bool quiet = false;      ///< plain progress lines every ~5 % instead of a live line
    bool overwrite = false;  ///< allow replacing another model's results in output_dir
    bool echo = true;        ///< print the log to stdout as well as log.txt
    /// Wall-clock seconds between restart files (DIR/restart.bin, replaced each time; one is
    /// also written when the run ends normally). 0: none. Dynamic runs only.
    double restart_every = 0;
    /// Continue the run held in output_dir from its restart file instead of starting afresh;
    /// the model may differ only in what does not change the state (end time, output cadence).
    bool resume = false;
    /// End the run after this step (counted from the start of the run, not of this segment),
    /// writing a restart file: LS-DYNA's ENDCYC, used by the tests. 0: no such limit.
    long stop_at_step = 0;
    /// More observers of the run (output_observer.hpp), told after the result files and before
    /// the closing lines of the log; not owned, they outlive the call.
    std::vector<OutputObserver*> observers;
};

/// Runs the model; returns the exit code (0 success, 1 the run failed: the last good state,
/// the histories and summary.json are written all the same; 128 + the signal number when a
/// dynamic run was interrupted by SIGINT or SIGTERM, after writing a restart file and every
/// result so far: driver/interrupt_guard.hpp). Throws InputError when the
/// output folder cannot be used or its restart file does not fit the model (exit 2).
int run_model(const Model& model, const RunOptions& options);

}  // namespace fpmshell
