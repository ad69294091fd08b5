// CSV table: formatting, atomic flush and a small reader for tests and tools.
#include "fpmshell/io/csv_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "fpmshell/io/atomic_file.hpp"

namespace fpmshell {

namespace {

std::string quote_if_needed(const std::string& field) {
    if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
    std::string out = "\"";
    for (const char c : field) {
        if (c == '"') out += '"';
        out += c;
    }
    out += '"';
    return out;
}

/// Splits one CSV line into fields, honouring RFC 4180 quotes (no line breaks inside quotes).
std::vector<std::string> split_line(std::string_view line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                fields.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                fields.back() += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    return fields;
}

}  // namespace

CsvTable::CsvTable(std::vector<std::string> header, int significant_digits)
    : header_(std::move(header)), digits_(significant_digits) {
    if (header_.empty()) throw std::invalid_argument("a CSV table needs at least one column.");
    if (digits_ < 0 || digits_ > 17) {
        throw std::invalid_argument(
            fmt::format("CSV precision {} is outside 0..17 significant digits.", digits_));
    }
    for (std::size_t j = 0; j < header_.size(); ++j) {
        if (j > 0) text_ += ',';
        text_ += quote_if_needed(header_[j]);
    }
    text_ += '\n';
}

void CsvTable::add_row(const std::vector<Real>& row) {
    if (row.size() != header_.size()) {
        throw std::invalid_argument(fmt::format(
            "CSV row has {} values but the table has {} columns.", row.size(), header_.size()));
    }
    auto out = std::back_inserter(text_);
    for (std::size_t j = 0; j < row.size(); ++j) {
        if (j > 0) text_ += ',';
        if (digits_ == 0) {
            fmt::format_to(out, "{}", row[j]);
        } else {
            fmt::format_to(out, "{:.{}g}", row[j], digits_);
        }
    }
    text_ += '\n';
    rows_.push_back(row);
}

void CsvTable::flush(const std::filesystem::path& path) const { write_file_atomic(path, text_); }

std::optional<std::size_t> CsvTable::column_index(std::string_view name) const {
    for (std::size_t j = 0; j < header_.size(); ++j) {
        if (header_[j] == name) return j;
    }
    return std::nullopt;
}

std::vector<Real> CsvTable::column(std::size_t j) const {
    if (j >= header_.size()) {
        throw std::out_of_range(
            fmt::format("CSV column {} does not exist; the table has {}.", j, header_.size()));
    }
    std::vector<Real> values;
    values.reserve(rows_.size());
    for (const auto& row : rows_) values.push_back(row[j]);
    return values;
}

CsvTable CsvTable::read(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open '" + path.string() + "' for reading.");
    std::string line;
    if (!std::getline(in, line)) {
        throw std::runtime_error("'" + path.string() + "' is empty; a header line was expected.");
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    CsvTable table(split_line(line), 0);
    int line_number = 1;
    while (std::getline(in, line)) {
        ++line_number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        const std::vector<std::string> fields = split_line(line);
        std::vector<Real> row;
        row.reserve(fields.size());
        for (const std::string& f : fields) {
            char* end = nullptr;
            const Real v = std::strtod(f.c_str(), &end);
            if (f.empty() || end == f.c_str() || *end != '\0') {
                throw std::runtime_error(
                    fmt::format("{}:{}: '{}' is not a number.", path.string(), line_number, f));
            }
            row.push_back(v);
        }
        if (row.size() != table.n_columns()) {
            throw std::runtime_error(
                fmt::format("{}:{}: {} values, but the header names {} columns.", path.string(),
                            line_number, row.size(), table.n_columns()));
        }
        table.add_row(row);
    }
    return table;
}

}  // namespace fpmshell
