// --set overrides (see overrides.hpp).
#include "fpmshell/io/overrides.hpp"

#include <charconv>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/text.hpp"

namespace fpmshell {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) {
    throw InputError(input_error_text("--set", 0, path, message));
}

/// What trim removes around the parts of an override: spaces and tabs.
constexpr std::string_view k_blanks = " \t";

std::vector<std::string> split_path(const std::string& path) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const auto dot = path.find('.', start);
        parts.push_back(
            path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    return parts;
}

/// Child `part` of `node` (a map key or a list index), or an invalid node (IsDefined false).
bool find_child(const YAML::Node& node, const std::string& part, YAML::Node& child) {
    if (node.IsMap()) {
        for (const auto& kv : node) {
            if (kv.first.IsScalar() && trim(kv.first.Scalar(), k_blanks) == part) {
                child.reset(kv.second);
                return true;
            }
        }
        return false;
    }
    if (node.IsSequence()) {
        std::size_t index = 0;
        const char* first = part.data();
        const char* last = part.data() + part.size();
        const auto [ptr, ec] = std::from_chars(first, last, index);
        if (ec != std::errc() || ptr != last || index >= node.size()) return false;
        std::size_t i = 0;
        for (const auto& item : node) {
            if (i++ == index) {
                child.reset(item);
                return true;
            }
        }
    }
    return false;
}

bool is_scalar_or_vector(const YAML::Node& node) {
    if (node.IsScalar()) return true;
    if (!node.IsSequence()) return false;
    for (const auto& item : node)
        if (!item.IsScalar()) return false;
    return true;
}

}  // namespace

void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides,
                     YamlContext& ctx) {
    for (const std::string& raw : overrides) {
        const auto eq = raw.find('=');
        if (eq == std::string::npos)
            fail(trim(raw, k_blanks),
                 "an override must look like key.path=value (for example "
                 "control.end_time=2e-3), got '" +
                     raw + "'");
        const std::string path = trim(raw.substr(0, eq), k_blanks);
        const std::string text = trim(raw.substr(eq + 1), k_blanks);
        if (path.empty()) fail("", "the override '" + raw + "' has no key path before '='");
        if (text.empty()) fail(path, "the override has no value after '='");

        YAML::Node target;
        target.reset(root);
        std::string walked;
        for (const std::string& part : split_path(path)) {
            if (part.empty()) fail(path, "the key path has an empty component");
            YAML::Node child;
            if (!find_child(target, part, child)) {
                const std::string where = walked.empty() ? "the model" : "'" + walked + "'";
                fail(path, "this key does not exist in the model file ('" + part +
                               "' is not found in " + where +
                               "); only keys written in the file can be overridden, list "
                               "items are numbered from 0");
            }
            walked = join_key(walked, part);
            target.reset(child);
        }
        if (!is_scalar_or_vector(target))
            fail(path,
                 "the key holds a map or a list of lists or maps; only a single value or a "
                 "list of numbers can be overridden");

        YAML::Node value;
        try {
            value = YAML::Load(text);
        } catch (const YAML::Exception& e) {
            fail(path, "the value '" + text + "' is not valid YAML (" + e.msg + ")");
        }
        if (!value.IsDefined() || value.IsNull())
            fail(path, "the value '" + text + "' is empty; give a number, a word or a list");
        target = value;  // replaces the node inside the tree (yaml-cpp assigns through handles)
        ctx.add_override(path);
    }
}

}  // namespace fpmshell
