// Result table observer; its cadence is described in csv_result_file.hpp.
#include "fpmshell/driver/csv_result_file.hpp"

#include <algorithm>
#include <utility>

#include "fpmshell/io/restart_archive.hpp"

namespace fpmshell {

CsvResultFile::CsvResultFile(std::filesystem::path path, std::vector<std::string> header,
                             std::string section, std::string columns_from)
    : path_(std::move(path)),
      table_(std::move(header)),
      section_(std::move(section)),
      columns_from_(std::move(columns_from)) {}

void CsvResultFile::load(RestartReader& restart) {
    restart.section(section_);
    std::vector<std::vector<Real>> rows;
    restart(rows);
    if (std::any_of(rows.begin(), rows.end(),
                    [&](const std::vector<Real>& r) { return r.size() != table_.n_columns(); }))
        restart.fail("restart file of a model with other " + columns_from_);
    for (const auto& r : rows) table_.add_row(r);
}

void CsvResultFile::start(const ExplicitSolver& /*solver*/) { flush(); }

void CsvResultFile::sample(const ExplicitSolver& solver, Real time, std::optional<bool> converged) {
    table_.add_row(row(solver, time, converged));
}

void CsvResultFile::frame(const ExplicitSolver& /*solver*/, Real /*time*/,
                          const std::vector<Vec3>& /*positions*/) {
    flush();
}

void CsvResultFile::step_done(const ExplicitSolver& /*solver*/, const StepReport& /*report*/) {
    if (std::chrono::duration<double>(Clock::now() - last_flush_).count() > k_flush_seconds)
        flush();
}

void CsvResultFile::finish(const ExplicitSolver& /*solver*/, const RunEnd& /*end*/) { flush(); }

void CsvResultFile::flush() {
    table_.flush(path_);
    last_flush_ = Clock::now();
}

void CsvResultFile::save(RestartWriter& restart) const {
    restart.section(section_);
    restart(table_.rows());
}

}  // namespace fpmshell
