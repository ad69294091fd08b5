// The report of a run on the terminal and in log.txt: the progress line (io/progress.hpp), the
// lines that say why the run stopped, and the closing lines.
#pragma once

#include "fpmshell/driver/output_observer.hpp"
#include "fpmshell/io/progress.hpp"
#include "fpmshell/io/run_directory.hpp"

namespace fpmshell {

/// The progress line, and the lines that say why a run stopped, written when the line is
/// closed. Observes first, so that they follow the last progress line and precede what the
/// other observers log.
class ProgressReport final : public OutputObserver {
public:
    /// `end_time`: the simulated time at 100 %; `quiet`: plain lines even on a terminal.
    ProgressReport(LogFile& log, Real end_time, bool quiet);
    ~ProgressReport() override;
    ProgressReport(const ProgressReport&) = delete;
    ProgressReport& operator=(const ProgressReport&) = delete;

    void start(const ExplicitSolver& solver) override;
    /// Shows the time, step and dt with the energy error (relaxation: the residual ratio).
    void step_done(const ExplicitSolver& solver, const StepReport& report) override;
    void failure(const ExplicitSolver& solver, std::string_view error,
                 const std::vector<Vec3>& last_good_positions) override;
    void finish(const ExplicitSolver& solver, const RunEnd& end) override;

private:
    LogFile& log_;
    Progress progress_;
};

/// The closing lines of log.txt: steps, time, energy error, wall time and speed, the contact
/// statistics and the result folder. Observes last, after every result file is written.
class ClosingReport final : public OutputObserver {
public:
    ClosingReport(LogFile& log, std::filesystem::path dir);

    void finish(const ExplicitSolver& solver, const RunEnd& end) override;

private:
    LogFile& log_;
    std::filesystem::path dir_;
};

}  // namespace fpmshell
