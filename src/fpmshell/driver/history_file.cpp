// history.csv: a row of the model's history requests per sample.
#include "fpmshell/driver/history_file.hpp"

#include <cmath>

#include "fpmshell/driver/history_sampler.hpp"

namespace fpmshell {

namespace {

std::vector<std::string> header(const Model& model) {
    std::vector<std::string> h{"time"};
    for (const HistoryRequest& r : model.output.histories) h.push_back(r.name);
    if (model.control.mode == SolutionMode::Relaxation) h.push_back("converged");
    return h;
}

}  // namespace

HistoryFile::HistoryFile(const Model& model, const std::filesystem::path& dir)
    : CsvResultFile(dir / "history.csv", header(model), "history", "output.histories"),
      model_(model) {}

std::vector<Real> HistoryFile::row(const ExplicitSolver& solver, Real time,
                                   std::optional<bool> converged) const {
    std::vector<Real> r{time};
    const std::vector<Real> values = sample_histories(model_, solver);
    r.insert(r.end(), values.begin(), values.end());
    if (converged) r.push_back(*converged ? 1.0 : 0.0);
    return r;
}

std::vector<HistoryFile::Peak> HistoryFile::peaks() const {
    std::vector<Peak> peaks(model_.output.histories.size());
    for (const std::vector<Real>& r : table().rows())
        for (std::size_t i = 0; i < peaks.size(); ++i)
            if (std::abs(r[i + 1]) > std::abs(peaks[i].value)) peaks[i] = {r[i + 1], r[0]};
    return peaks;
}

}  // namespace fpmshell
