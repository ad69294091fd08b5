// Typed, checked access to a parsed YAML model file. Every value carries its dotted key path
// ("loads.0.value") and its line, so any problem becomes the one-sentence InputError of the
// user contract: "FILE:LINE: key 'a.b.c': what is wrong and what is expected".
// Only const access is used on the tree (yaml-cpp's non-const operator[] inserts keys).
#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// Where messages point: the model file, and the key paths replaced by --set (whose values
/// have no line in the file; their messages name "--set" instead).
class YamlContext {
public:
    explicit YamlContext(std::string file) : file_(std::move(file)) {}

    [[nodiscard]] const std::string& file() const { return file_; }
    /// Records that `path` (and everything below it) was replaced by a --set override.
    void add_override(const std::string& path) { overrides_.push_back(path); }
    [[nodiscard]] bool is_overridden(const std::string& path) const;

    /// Throws InputError "FILE:LINE: key 'path': message" (line of `node` when it has one).
    [[noreturn]] void fail(const YAML::Node& node, const std::string& path,
                           const std::string& message) const;
    /// Same with an explicit 1-based line (<= 0: none).
    [[noreturn]] void fail_at(int line, const std::string& path, const std::string& message) const;

    /// Where each line of a generated model file comes from (a translated keyword deck): the
    /// messages then name that file and line instead.
    void set_line_origins(std::vector<SourceLine> origins) { origins_ = std::move(origins); }

private:
    std::string file_;
    std::vector<SourceLine> origins_;
    std::vector<std::string> overrides_;
};

/// 1-based line of a node, 0 when it has none.
[[nodiscard]] int yaml_line(const YAML::Node& node);

/// "a.b" + "c" -> "a.b.c" (no dot when the parent path is empty).
[[nodiscard]] std::string join_key(const std::string& parent, const std::string& key);

/// The candidate closest to a mistyped `word` (small edit distance, or a different case),
/// or "" when none is close.
[[nodiscard]] std::string closest_name(const std::string& word,
                                       const std::vector<std::string>& candidates);

/// " (did you mean 'x'?)" when closest_name finds one, else "".
[[nodiscard]] std::string did_you_mean(const std::string& word,
                                       const std::vector<std::string>& candidates);

/// "a, b, c" (names joined for messages; long lists are cut with ", ...").
[[nodiscard]] std::string join_names(const std::vector<std::string>& names);

class YamlMap;

/// A value of the tree with its key path. Accessors check the type and throw InputError.
class YamlValue {
public:
    /// `key_line`: line of the key that holds this value in its map (0: none, a list item or
    /// the root); messages about the value point there, since block maps and lists start on
    /// the line after their key.
    YamlValue(const YamlContext& ctx, YAML::Node node, std::string path, int key_line = 0)
        : ctx_(&ctx), node_(std::move(node)), path_(std::move(path)), key_line_(key_line) {}

    [[nodiscard]] const std::string& path() const { return path_; }
    [[nodiscard]] const YAML::Node& node() const { return node_; }
    [[nodiscard]] const YamlContext& context() const { return *ctx_; }
    /// Line of the key holding the value, else of the value itself (1-based, 0 if none).
    [[nodiscard]] int line() const { return key_line_ > 0 ? key_line_ : yaml_line(node_); }
    [[noreturn]] void fail(const std::string& message) const;

    [[nodiscard]] bool is_map() const { return node_.IsMap(); }
    [[nodiscard]] bool is_list() const { return node_.IsSequence(); }
    [[nodiscard]] bool is_scalar() const { return node_.IsScalar(); }
    [[nodiscard]] bool is_null() const { return node_.IsNull(); }
    /// "a list", "a map", "nothing" or the quoted scalar text, for messages.
    [[nodiscard]] std::string describe() const;

    /// A finite number.
    [[nodiscard]] Real real() const;
    /// A finite number > 0.
    [[nodiscard]] Real positive() const;
    /// A finite number >= 0.
    [[nodiscard]] Real non_negative() const;
    /// A whole number in [min, max] (written 12, 12.0 or 1.2e1).
    [[nodiscard]] long long integer(long long min, long long max) const;
    /// Any scalar, as written.
    [[nodiscard]] std::string text() const;
    /// A non-empty scalar (a set, material or curve name, an option word).
    [[nodiscard]] std::string name() const;
    /// One of `choices` (the message lists them).
    [[nodiscard]] std::string choice(const std::vector<std::string>& choices) const;
    /// A list of exactly 3 finite numbers.
    [[nodiscard]] Vec3 vec3() const;
    /// The items of a list (paths "path.0", "path.1", ...). `what` describes one item.
    [[nodiscard]] std::vector<YamlValue> list(const std::string& what = "") const;
    /// The items of a list of exactly n items; otherwise fails "expected `expected`, got a
    /// list of k items" (or what the value is).
    [[nodiscard]] std::vector<YamlValue> list_of(std::size_t n, const std::string& what,
                                                 const std::string& expected) const;
    /// A map whose keys must all be in `allowed` (unknown keys are rejected with suggestions).
    [[nodiscard]] YamlMap map(const std::vector<std::string>& allowed) const;
    /// A map with free keys (names of sets, materials, curves).
    [[nodiscard]] YamlMap open_map(const std::string& what) const;

private:
    const YamlContext* ctx_;
    YAML::Node node_;
    std::string path_;
    int key_line_ = 0;
};

/// A YAML map with its entries in file order; duplicate and non-scalar keys are rejected.
class YamlMap {
public:
    YamlMap(const YamlValue& self, const std::vector<std::string>* allowed,
            const std::string& what);

    [[nodiscard]] const YamlValue& self() const { return self_; }
    [[nodiscard]] bool has(const std::string& key) const;
    [[nodiscard]] std::optional<YamlValue> find(const std::string& key) const;
    /// Value of a required key (missing: error at the map's line, naming `expected`).
    [[nodiscard]] YamlValue at(const std::string& key, const std::string& expected = "") const;
    [[nodiscard]] const std::vector<std::pair<std::string, YamlValue>>& entries() const {
        return entries_;
    }
    /// Number of keys of `keys` present.
    [[nodiscard]] int count(std::initializer_list<const char*> keys) const;

    // Shorthands for optional keys with defaults.
    [[nodiscard]] Real real_or(const std::string& key, Real fallback) const;
    [[nodiscard]] Real positive_or(const std::string& key, Real fallback) const;
    [[nodiscard]] Real non_negative_or(const std::string& key, Real fallback) const;
    [[nodiscard]] std::string choice_or(const std::string& key,
                                        const std::vector<std::string>& choices,
                                        const std::string& fallback) const;

private:
    YamlValue self_;
    std::vector<std::pair<std::string, YamlValue>> entries_;
};

}  // namespace fpmshell
