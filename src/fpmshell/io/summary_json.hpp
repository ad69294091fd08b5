// A minimal JSON value and writer for summary.json (model-format.md "Results in DIR").
// Objects keep their keys in insertion order, so the file reads in the order it was built.
// Numbers are written in the shortest form that reads back to the same double (at most 17
// significant digits, so nothing is lost); NaN and infinities, which JSON cannot hold, become
// null. Strings are escaped as RFC 8259 requires; UTF-8 passes through unchanged.
#pragma once

#include <concepts>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace fpmshell {

class JsonValue {
public:
    using Array = std::vector<JsonValue>;
    using Object = std::vector<std::pair<std::string, JsonValue>>;  ///< ordered, unique keys

    JsonValue() = default;  ///< null
    JsonValue(std::nullptr_t) {}
    JsonValue(bool b) : value_(b) {}
    /// Any integer or floating-point number (stored as a double).
    template <class T>
    requires(std::integral<T> || std::floating_point<T>) && (!std::same_as<T, bool>)JsonValue(T x)
        : value_(static_cast<double>(x)) {}
    JsonValue(const char* s) : value_(std::string(s)) {}
    JsonValue(std::string s) : value_(std::move(s)) {}
    JsonValue(std::string_view s) : value_(std::string(s)) {}
    JsonValue(Array a) : value_(std::move(a)) {}
    JsonValue(Object o) : value_(std::move(o)) {}

    [[nodiscard]] static JsonValue object() { return JsonValue(Object{}); }
    [[nodiscard]] static JsonValue array() { return JsonValue(Array{}); }

    [[nodiscard]] bool is_null() const { return std::holds_alternative<std::nullptr_t>(value_); }
    [[nodiscard]] bool is_bool() const { return std::holds_alternative<bool>(value_); }
    [[nodiscard]] bool is_number() const { return std::holds_alternative<double>(value_); }
    [[nodiscard]] bool is_string() const { return std::holds_alternative<std::string>(value_); }
    [[nodiscard]] bool is_array() const { return std::holds_alternative<Array>(value_); }
    [[nodiscard]] bool is_object() const { return std::holds_alternative<Object>(value_); }

    /// Typed access; std::bad_variant_access when the value holds another type.
    [[nodiscard]] bool as_bool() const { return std::get<bool>(value_); }
    [[nodiscard]] double as_number() const { return std::get<double>(value_); }
    [[nodiscard]] const std::string& as_string() const { return std::get<std::string>(value_); }
    [[nodiscard]] const Array& as_array() const { return std::get<Array>(value_); }
    [[nodiscard]] const Object& as_object() const { return std::get<Object>(value_); }
    [[nodiscard]] Array& as_array() { return std::get<Array>(value_); }
    [[nodiscard]] Object& as_object() { return std::get<Object>(value_); }

    /// Object member `key`, added as null at the end when missing. A null value becomes an
    /// empty object first, so `v["peaks"]["apex_w"]["value"] = 1.0` builds nested objects.
    /// std::bad_variant_access when the value is neither null nor an object.
    JsonValue& operator[](std::string_view key);
    /// Sets member `key` (replacing its value, or appending it); returns *this for chaining.
    JsonValue& set(std::string_view key, JsonValue v);
    /// Member `key`, or nullptr when the value is not an object or has no such key.
    [[nodiscard]] const JsonValue* find(std::string_view key) const;
    /// Appends to an array (a null value becomes an empty array first).
    void push_back(JsonValue v);

private:
    std::variant<std::nullptr_t, bool, double, std::string, Array, Object> value_{nullptr};
};

/// JSON text of `value`. indent > 0: pretty-printed with that many spaces per level;
/// indent <= 0: compact, on one line. No trailing newline.
[[nodiscard]] std::string to_json(const JsonValue& value, int indent = 2);

/// The JSON string literal of `s` (quotes included), escaped as RFC 8259 requires.
[[nodiscard]] std::string json_quote(std::string_view s);

/// Writes to_json(value, 2) plus a newline to `path`, atomically (std::runtime_error on failure).
void write_json_file(const std::filesystem::path& path, const JsonValue& value);

}  // namespace fpmshell
