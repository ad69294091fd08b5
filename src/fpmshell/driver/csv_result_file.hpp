// A result table of the run (history.csv, energy.csv) as an observer: one row per history
// sample, rewritten whole (atomically) at start, at every frame, at least every 2 s of wall time,
// on flush and at the end (model-format.md "Results in DIR"); its rows travel in restart.bin.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "fpmshell/driver/output_observer.hpp"
#include "fpmshell/io/csv_table.hpp"

namespace fpmshell {

class CsvResultFile : public OutputObserver {
public:
    /// Wall seconds after which the rows are written even without a frame.
    static constexpr double k_flush_seconds = 2.0;

    [[nodiscard]] const CsvTable& table() const { return table_; }

    void load(RestartReader& restart) override;
    void start(const ExplicitSolver& solver) override;
    void sample(const ExplicitSolver& solver, Real time, std::optional<bool> converged) override;
    void frame(const ExplicitSolver& solver, Real time,
               const std::vector<Vec3>& positions) override;
    void step_done(const ExplicitSolver& solver, const StepReport& report) override;
    void finish(const ExplicitSolver& solver, const RunEnd& end) override;
    void flush() override;
    void save(RestartWriter& restart) const override;

protected:
    /// `section`: the name of the table's section in restart.bin; `columns_from`: what sets
    /// the columns, named when a restart file's rows do not fit them.
    CsvResultFile(std::filesystem::path path, std::vector<std::string> header, std::string section,
                  std::string columns_from);

    /// The row of the sample at `time`, one value per column.
    [[nodiscard]] virtual std::vector<Real> row(const ExplicitSolver& solver, Real time,
                                                std::optional<bool> converged) const = 0;

private:
    using Clock = std::chrono::steady_clock;

    std::filesystem::path path_;
    CsvTable table_;
    std::string section_;
    std::string columns_from_;
    Clock::time_point last_flush_ = Clock::now();
};

}  // namespace fpmshell
