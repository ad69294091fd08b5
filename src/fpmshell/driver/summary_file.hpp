// summary.json (model-format.md "Results in DIR", its keys in that order): the model, the
// steps, the speed, the peaks of the histories, the plastic strain, contact statistics, the
// rigid bodies and how the run ended; written once, at the end of the run.
#pragma once

#include <filesystem>
#include <optional>

#include "fpmshell/driver/history_file.hpp"
#include "fpmshell/driver/output_observer.hpp"
#include "fpmshell/driver/plastic_strain_peaks.hpp"

namespace fpmshell {

class SummaryFile final : public OutputObserver {
public:
    /// `history`: the run's history.csv, whose rows give the peaks.
    SummaryFile(const Model& model, std::filesystem::path dir, const HistoryFile& history);

    /// The plastic strain peaks of a distributed run, reduced over the ranks by every rank
    /// before the end (plastic_strain_peaks is collective); a single process's are taken at
    /// the end when none were given.
    void set_plastic_strain_peaks(const PlasticStrainPeaks& peaks) { plastic_strain_ = peaks; }

    void finish(const ExplicitSolver& solver, const RunEnd& end) override;

private:
    const Model& model_;
    std::filesystem::path dir_;
    const HistoryFile& history_;
    std::optional<PlasticStrainPeaks> plastic_strain_;
};

}  // namespace fpmshell
