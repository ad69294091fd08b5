// JSON writer for summary.json; format notes are in summary_json.hpp.
#include "fpmshell/io/summary_json.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

#include "fpmshell/io/atomic_file.hpp"

namespace fpmshell {

JsonValue& JsonValue::operator[](std::string_view key) {
    if (is_null()) value_ = Object{};
    Object& members = std::get<Object>(value_);
    for (auto& [name, v] : members) {
        if (name == key) return v;
    }
    members.emplace_back(std::string(key), JsonValue());
    return members.back().second;
}

JsonValue& JsonValue::set(std::string_view key, JsonValue v) {
    (*this)[key] = std::move(v);
    return *this;
}

const JsonValue* JsonValue::find(std::string_view key) const {
    if (!is_object()) return nullptr;
    for (const auto& [name, v] : std::get<Object>(value_)) {
        if (name == key) return &v;
    }
    return nullptr;
}

void JsonValue::push_back(JsonValue v) {
    if (is_null()) value_ = Array{};
    std::get<Array>(value_).push_back(std::move(v));
}

std::string json_quote(std::string_view s) {
    std::string out;
    out.reserve(s.size() + 2);
    out += '"';
    for (const char c : s) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\b':
                out += "\\b";
                break;
            case '\f':
                out += "\\f";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    fmt::format_to(std::back_inserter(out), "\\u{:04x}",
                                   static_cast<unsigned>(static_cast<unsigned char>(c)));
                } else {
                    out += c;
                }
        }
    }
    out += '"';
    return out;
}

namespace {

void write_value(std::string& out, const JsonValue& v, int indent, int level) {
    const bool pretty = indent > 0;
    auto newline = [&](int lvl) {
        if (!pretty) return;
        out += '\n';
        out.append(static_cast<std::size_t>(indent) * static_cast<std::size_t>(lvl), ' ');
    };
    if (v.is_null()) {
        out += "null";
    } else if (v.is_bool()) {
        out += v.as_bool() ? "true" : "false";
    } else if (v.is_number()) {
        const double x = v.as_number();
        if (std::isfinite(x)) {
            fmt::format_to(std::back_inserter(out), "{}", x);  // shortest round-trip form
        } else {
            out += "null";  // JSON has no NaN or infinity
        }
    } else if (v.is_string()) {
        out += json_quote(v.as_string());
    } else if (v.is_array()) {
        const auto& a = v.as_array();
        if (a.empty()) {
            out += "[]";
            return;
        }
        out += '[';
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (i > 0) out += ',';
            newline(level + 1);
            write_value(out, a[i], indent, level + 1);
        }
        newline(level);
        out += ']';
    } else {
        const auto& o = v.as_object();
        if (o.empty()) {
            out += "{}";
            return;
        }
        out += '{';
        for (std::size_t i = 0; i < o.size(); ++i) {
            if (i > 0) out += ',';
            newline(level + 1);
            out += json_quote(o[i].first);
            out += pretty ? ": " : ":";
            write_value(out, o[i].second, indent, level + 1);
        }
        newline(level);
        out += '}';
    }
}

}  // namespace

std::string to_json(const JsonValue& value, int indent) {
    std::string out;
    write_value(out, value, indent, 0);
    return out;
}

void write_json_file(const std::filesystem::path& path, const JsonValue& value) {
    write_file_atomic(path, to_json(value, 2) + "\n");
}

}  // namespace fpmshell
