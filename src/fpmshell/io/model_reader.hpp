// Reads and validates the YAML model file of model-format.md into a Model (the "Starter").
#pragma once

#include <string>
#include <vector>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// Parses the model file at `path`, applies the --set overrides ("a.b.c=value", see
/// io/overrides.hpp) and returns the validated Model. Relative mesh file paths are taken
/// relative to the folder of `path`.
///
/// Rules where model-format.md is silent:
/// - `sections` are applied in order; a later entry overrides an earlier one on the elements
///   they share. Every element must end up with a section.
/// - Set members are 0-based and sorted; every model has the node and element set `all`.
/// - `initial_conditions` entries need `velocity` and/or `angular_velocity`; later entries
///   override earlier ones on shared nodes (the solver applies them in order).
///
/// Throws InputError with one sentence "FILE:LINE: key 'a.b.c': what is wrong and what is
/// expected" on any problem (including YAML syntax errors and a missing file). Never crashes
/// or hangs on malformed input.
[[nodiscard]] Model read_model(const std::string& path,
                               const std::vector<std::string>& set_overrides = {});

/// As read_model, for a model file generated from `source` (a keyword deck, io/lsdyna_deck.hpp):
/// `yaml` is its text, origins[k] the place in the deck that line k + 1 comes from (messages
/// name it), mesh files are relative to the folder of `source`, and the model is named after it.
[[nodiscard]] Model read_model_text(const std::string& yaml, std::vector<SourceLine> origins,
                                    const std::string& source,
                                    const std::vector<std::string>& set_overrides = {});

}  // namespace fpmshell
