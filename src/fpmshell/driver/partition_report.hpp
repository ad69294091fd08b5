// `fpmshell partition MODEL --parts N`: how the model's element loop would be cut for a
// distributed run (solver/unit_partition.hpp), part by part, with the halo traffic per step.
#pragma once

#include <string>

#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// The table of the cut of `model` into n_parts parts (n_parts >= 1; more than 1 needs METIS:
/// partitioning_available()).
[[nodiscard]] std::string partition_report(const Model& model, int n_parts);

}  // namespace fpmshell
