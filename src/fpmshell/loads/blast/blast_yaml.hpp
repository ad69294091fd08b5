// `loads: - {type: blast, ...}` (docs/model-format.md): the keys of an air blast, checked.
#pragma once

#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/loads/blast/blast_load.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// The blast of a `loads` entry whose type is blast, its sets looked up in `model`.
[[nodiscard]] BlastLoad read_blast_load(const YamlValue& item, const Model& model);

}  // namespace fpmshell
