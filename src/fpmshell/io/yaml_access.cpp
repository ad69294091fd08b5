// Typed, checked access to the YAML tree (see yaml_access.hpp).
#include "fpmshell/io/yaml_access.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <system_error>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/text.hpp"

namespace fpmshell {
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

/// Optimal string alignment distance (insertions, deletions, substitutions and swaps of
/// neighbouring letters each cost 1), for "did you mean" suggestions.
std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0U : 1U;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[a.size()][b.size()];
}

enum class NumberStatus { Ok, NotANumber, NotFinite, OutOfRange };

/// Parses a YAML scalar as a double: plain decimal or exponent notation, optional sign;
/// YAML's .inf / .nan (and inf / nan) are recognised so that they can be refused by name.
NumberStatus parse_number(const std::string& raw, double& value) {
    std::string s = trim(raw);
    if (s.empty() || s.size() > 400) return NumberStatus::NotANumber;
    const std::string l = lower(s);
    for (const char* word : {".inf", "+.inf", "-.inf", ".nan", "inf", "-inf", "+inf", "nan",
                             "infinity", "-infinity", "+infinity"})
        if (l == word) return NumberStatus::NotFinite;
    if (s.front() == '+') s.erase(0, 1);
    if (s.empty() || !(std::isdigit(static_cast<unsigned char>(s.front())) || s.front() == '-' ||
                       s.front() == '.'))
        return NumberStatus::NotANumber;
    const char* first = s.data();
    const char* last = s.data() + s.size();
    const auto [ptr, ec] = std::from_chars(first, last, value, std::chars_format::general);
    if (ec == std::errc::result_out_of_range) return NumberStatus::OutOfRange;
    if (ec != std::errc() || ptr != last) return NumberStatus::NotANumber;
    if (!std::isfinite(value)) return NumberStatus::NotFinite;
    return NumberStatus::Ok;
}

}  // namespace

// ---- free helpers ----

int yaml_line(const YAML::Node& node) {
    try {
        if (!node.IsDefined()) return 0;
        const YAML::Mark mark = node.Mark();
        if (mark.is_null() || mark.line < 0) return 0;
        return mark.line + 1;
    } catch (const YAML::Exception&) {
        return 0;
    }
}

std::string join_key(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

std::string closest_name(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t best_distance = 0;
    constexpr std::size_t k_max_length = 64;  // suggestions are for typos in short names
    if (word.size() > k_max_length) return best;
    const std::string lw = lower(word);
    for (const auto& c : candidates) {
        if (c.size() > k_max_length) continue;
        if (lower(c) == lw) return c;
        const std::size_t d = edit_distance(lw, lower(c));
        const std::size_t limit = std::max<std::size_t>(1, std::min(word.size(), c.size()) / 3);
        const bool prefix = word.size() >= 3 && lower(c).rfind(lw, 0) == 0;
        if ((d <= limit || prefix) && (best.empty() || d < best_distance)) {
            best = c;
            best_distance = d;
        }
    }
    return best;
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
    const std::string best = closest_name(word, candidates);
    return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

std::string join_names(const std::vector<std::string>& names) {
    constexpr std::size_t k_max = 30;
    std::string out;
    for (std::size_t i = 0; i < names.size() && i < k_max; ++i) {
        if (i > 0) out += ", ";
        out += names[i];
    }
    if (names.size() > k_max) out += ", ...";
    return out;
}

// ---- YamlContext ----

bool YamlContext::is_overridden(const std::string& path) const {
    return std::any_of(overrides_.begin(), overrides_.end(), [&](const std::string& o) {
        return path == o || (path.size() > o.size() && path.compare(0, o.size(), o) == 0 &&
                             path[o.size()] == '.');
    });
}

void YamlContext::fail(const YAML::Node& node, const std::string& path,
                       const std::string& message) const {
    fail_at(yaml_line(node), path, message);
}

void YamlContext::fail_at(int line, const std::string& path, const std::string& message) const {
    if (is_overridden(path)) throw InputError(input_error_text("--set", 0, path, message));
    if (line > 0 && static_cast<std::size_t>(line) <= origins_.size()) {
        const SourceLine& o = origins_[static_cast<std::size_t>(line - 1)];
        if (o.card.empty()) throw InputError(input_error_text(o.file, o.line, path, message));
        throw InputError(input_error_text(o.file, o.line, "",
                                          o.card + " (model key '" + path + "'): " + message));
    }
    if (!origins_.empty()) line = 0;  // a line of the generated file means nothing to the user
    throw InputError(input_error_text(file_, line, path, message));
}

// ---- YamlValue ----

void YamlValue::fail(const std::string& message) const { ctx_->fail_at(line(), path_, message); }

std::string YamlValue::describe() const {
    if (!node_.IsDefined() || node_.IsNull()) return "nothing";
    if (node_.IsSequence()) return "a list";
    if (node_.IsMap()) return "a map";
    std::string s = node_.Scalar();
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return "'" + s + "'";
}

Real YamlValue::real() const {
    if (!is_scalar()) fail("expected a number, got " + describe());
    double v = 0;
    switch (parse_number(node_.Scalar(), v)) {
        case NumberStatus::Ok:
            return v;
        case NumberStatus::NotFinite:
            fail("expected a finite number, got " + describe());
        case NumberStatus::OutOfRange:
            fail("the number " + describe() + " is out of the range of double precision");
        case NumberStatus::NotANumber:
            break;
    }
    fail("expected a number, got " + describe());
}

Real YamlValue::positive() const {
    const Real v = real();
    if (!(v > 0)) fail("must be greater than 0, got " + describe());
    return v;
}

Real YamlValue::non_negative() const {
    const Real v = real();
    if (!(v >= 0)) fail("must be 0 or more, got " + describe());
    return v;
}

long long YamlValue::integer(long long min, long long max) const {
    const std::string range =
        "a whole number from " + std::to_string(min) + " to " + std::to_string(max);
    if (!is_scalar()) fail("expected " + range + ", got " + describe());
    double v = 0;
    if (parse_number(node_.Scalar(), v) != NumberStatus::Ok || v != std::floor(v) ||
        v < static_cast<double>(min) || v > static_cast<double>(max))
        fail("expected " + range + ", got " + describe());
    return static_cast<long long>(v);
}

std::string YamlValue::text() const {
    if (!is_scalar()) fail("expected a text, got " + describe());
    return node_.Scalar();
}

std::string YamlValue::name() const {
    if (!is_scalar()) fail("expected a name, got " + describe());
    std::string s = trim(node_.Scalar());
    if (s.empty()) fail("expected a name, got an empty text");
    return s;
}

std::string YamlValue::choice(const std::vector<std::string>& choices) const {
    if (!is_scalar()) fail("expected one of " + join_names(choices) + ", got " + describe());
    const std::string s = trim(node_.Scalar());
    if (std::find(choices.begin(), choices.end(), s) == choices.end())
        fail("expected one of " + join_names(choices) + ", got " + describe() +
             did_you_mean(s, choices));
    return s;
}

Vec3 YamlValue::vec3() const {
    if (!is_list() || node_.size() != 3)
        fail("expected a list of 3 numbers [x, y, z], got " +
             (is_list() ? "a list of " + std::to_string(node_.size()) + " items" : describe()));
    Vec3 v;
    const auto items = list();
    for (int i = 0; i < 3; ++i) v[i] = items[static_cast<std::size_t>(i)].real();
    return v;
}

std::vector<YamlValue> YamlValue::list(const std::string& what) const {
    std::vector<YamlValue> items;
    if (is_null()) return items;
    if (!is_list())
        fail("expected a list" + (what.empty() ? std::string() : " of " + what) + ", got " +
             describe());
    std::size_t i = 0;
    for (const auto& item : node_) {
        items.emplace_back(*ctx_, item, join_key(path_, std::to_string(i)));
        ++i;
    }
    return items;
}

std::vector<YamlValue> YamlValue::list_of(std::size_t n, const std::string& what,
                                          const std::string& expected) const {
    auto items = list(what);
    if (items.size() != n)
        fail("expected " + expected + ", got " +
             (is_list() ? "a list of " + std::to_string(items.size()) + " items" : describe()));
    return items;
}

YamlMap YamlValue::map(const std::vector<std::string>& allowed) const {
    return YamlMap(*this, &allowed, "");
}

YamlMap YamlValue::open_map(const std::string& what) const { return YamlMap(*this, nullptr, what); }

// ---- YamlMap ----

YamlMap::YamlMap(const YamlValue& self, const std::vector<std::string>* allowed,
                 const std::string& what)
    : self_(self) {
    if (self.is_null()) return;
    if (!self.is_map()) {
        std::string expected = "expected a map";
        if (!what.empty()) expected += " of " + what;
        if (allowed != nullptr && !allowed->empty())
            expected += " with keys such as " + join_names(*allowed);
        self.fail(expected + ", got " + self.describe());
    }
    const YamlContext& ctx = self.context();
    for (const auto& kv : self.node()) {
        const YAML::Node& key = kv.first;
        if (!key.IsScalar() || trim(key.Scalar()).empty())
            ctx.fail(key, self.path(), "keys must be plain names, got a complex or empty key");
        const std::string name = trim(key.Scalar());
        const std::string path = join_key(self.path(), name);
        for (const auto& [other, value] : entries_)
            if (other == name)
                ctx.fail(key, path,
                         "appears twice in the same map (first at line " +
                             std::to_string(value.line()) + "); keep only one");
        if (allowed != nullptr &&
            std::find(allowed->begin(), allowed->end(), name) == allowed->end()) {
            const std::string where =
                self.path().empty() ? "at the top level" : "under '" + self.path() + "'";
            ctx.fail(key, path,
                     "unknown key" + did_you_mean(name, *allowed) + "; valid keys " + where +
                         " are " + join_names(*allowed));
        }
        entries_.emplace_back(name, YamlValue(ctx, kv.second, path, yaml_line(key)));
    }
}

bool YamlMap::has(const std::string& key) const { return find(key).has_value(); }

std::optional<YamlValue> YamlMap::find(const std::string& key) const {
    for (const auto& [name, value] : entries_)
        if (name == key) return value;
    return std::nullopt;
}

YamlValue YamlMap::at(const std::string& key, const std::string& expected) const {
    if (auto v = find(key)) return *v;
    self_.context().fail_at(
        self_.line(), join_key(self_.path(), key),
        "is required but missing" + (expected.empty() ? std::string() : "; expected " + expected));
}

int YamlMap::count(std::initializer_list<const char*> keys) const {
    int n = 0;
    for (const char* k : keys)
        if (has(k)) ++n;
    return n;
}

Real YamlMap::real_or(const std::string& key, Real fallback) const {
    const auto v = find(key);
    return v ? v->real() : fallback;
}

Real YamlMap::positive_or(const std::string& key, Real fallback) const {
    const auto v = find(key);
    return v ? v->positive() : fallback;
}

Real YamlMap::non_negative_or(const std::string& key, Real fallback) const {
    const auto v = find(key);
    return v ? v->non_negative() : fallback;
}

std::string YamlMap::choice_or(const std::string& key, const std::vector<std::string>& choices,
                               const std::string& fallback) const {
    const auto v = find(key);
    return v ? v->choice(choices) : fallback;
}

}  // namespace fpmshell
