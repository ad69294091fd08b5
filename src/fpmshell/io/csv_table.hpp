// A table of numbers kept in memory and written as CSV: history.csv and energy.csv
// (model-format.md "Results in DIR"). The file is rewritten whole and atomically at every
// flush, so a run killed at any moment leaves a complete, readable table.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

class CsvTable {
public:
    /// Default number of significant digits of every value (printf "%.10g").
    static constexpr int k_default_digits = 10;

    /// `header` names the columns (for example {"time", "apex_w"}); a name holding a comma, a
    /// quote or a line break is quoted as RFC 4180 says. `significant_digits` is the precision
    /// of every value ("%.<digits>g"); 0 means the shortest text that reads back to the same
    /// double. Throws std::invalid_argument for an empty header or digits outside 0..17.
    explicit CsvTable(std::vector<std::string> header, int significant_digits = k_default_digits);

    /// Appends one row; it must have one value per column (std::invalid_argument otherwise).
    /// NaN and infinities are written as nan, inf and -inf (Python and NumPy read them).
    void add_row(const std::vector<Real>& row);

    /// Rewrites the whole file at `path` atomically (header and every row so far).
    /// Throws std::runtime_error when the file cannot be written.
    void flush(const std::filesystem::path& path) const;

    [[nodiscard]] const std::vector<std::string>& header() const { return header_; }
    [[nodiscard]] const std::vector<std::vector<Real>>& rows() const { return rows_; }
    [[nodiscard]] std::size_t n_rows() const { return rows_.size(); }
    [[nodiscard]] std::size_t n_columns() const { return header_.size(); }
    /// Index of the column called `name`, if there is one.
    [[nodiscard]] std::optional<std::size_t> column_index(std::string_view name) const;
    /// All values of column `j` (std::out_of_range when there is no such column).
    [[nodiscard]] std::vector<Real> column(std::size_t j) const;
    /// The file content flush() writes.
    [[nodiscard]] const std::string& text() const { return text_; }

    /// Reads a CSV file written by flush() (or any comma-separated file with one header line
    /// and numeric rows). Throws std::runtime_error naming the file and line on a bad row.
    [[nodiscard]] static CsvTable read(const std::filesystem::path& path);

private:
    std::vector<std::string> header_;
    std::vector<std::vector<Real>> rows_;
    int digits_;
    std::string text_;  ///< formatted once per row, so a flush is a single write
};

}  // namespace fpmshell
