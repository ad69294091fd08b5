// summary.json (model-format.md "Results in DIR", its keys in that order): the model, the
// steps, the speed, the peaks of the histories, the plastic strain, contact statistics, the
// rigid bodies and how the run ended; written once, at the end of the run.
#pragma once

#include <filesystem>

#include "fpmshell/driver/history_file.hpp"
#include "fpmshell/driver/output_observer.hpp"

namespace fpmshell {

class SummaryFile final : public OutputObserver {
public:
    /// `history`: the run's history.csv, whose rows give the peaks.
    SummaryFile(const Model& model, std::filesystem::path dir, const HistoryFile& history);

    void finish(const ExplicitSolver& solver, const RunEnd& end) override;

private:
    const Model& model_;
    std::filesystem::path dir_;
    const HistoryFile& history_;
};

}  // namespace fpmshell
