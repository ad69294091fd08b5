// The text `fpmshell check` prints (model-format.md "Command line").
#pragma once

#include <string>

#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// Counts, total mass, sets, rigid bodies, contacts, the stable step and the number of steps
/// (relaxation: of load levels).
[[nodiscard]] std::string model_summary(const Model& model);

}  // namespace fpmshell
