// --set overrides of the command line (model-format.md: `--set control.end_time=2e-3`).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "fpmshell/io/yaml_access.hpp"

namespace fpmshell {

/// Applies overrides "a.b.c=value" to the parsed model tree `root` (a map), in order (a later
/// one wins). The path walks map keys by name and list items by 0-based index
/// ("loads.0.value=700"). The target must already exist and hold a scalar or a list of
/// scalars (a vector such as [0, 0, -1]); maps and lists of lists or maps cannot be replaced.
/// The value is parsed as YAML, so "[1, 2, 3]" gives a list. Each overridden path is recorded
/// in `ctx`, so later messages about it name "--set" instead of a line of the file.
/// Throws InputError "--set: key 'PATH': ..." for a malformed override or a path that does
/// not exist.
void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides, YamlContext& ctx);

}  // namespace fpmshell
