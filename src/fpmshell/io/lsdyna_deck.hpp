// An LS-DYNA keyword deck translated into the YAML model of model-format.md: the cards fpmshell
// can honour become model keys (docs/decks.md), the cards whose absence cannot change
// the physics (output requests, titles) are ignored with a note, and any other card is refused
// with its file, line and keyword. The mesh (nodes, shells, sets) stays in the deck: the model's
// `mesh.file` names it (mesh/lsdyna_reader.hpp).
#pragma once

#include <string>
#include <vector>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// The YAML model of a deck, line by line with the place in the deck each line comes from.
struct DeckTranslation {
    std::string yaml;
    std::vector<SourceLine> origins;  ///< origins[k]: the deck card of line k + 1 of yaml
    std::vector<std::string> notes;   ///< "FILE:LINE: *KEYWORD: ..." for what was ignored or mapped
};

/// True for the file names of keyword decks: .k, .key, .dyn, .kw (any case).
[[nodiscard]] bool is_keyword_deck(const std::string& path);

/// Translates the deck at `deck_path`; the model's `mesh.file` is `mesh_file` (the deck as the
/// YAML file's folder sees it). Throws InputError "FILE:LINE: *KEYWORD: ..." for a card that
/// is malformed, refers to something undefined, or asks for what fpmshell cannot do.
[[nodiscard]] DeckTranslation translate_lsdyna_deck(const std::string& deck_path,
                                                    const std::string& mesh_file);

/// The validated model of a deck (translate_lsdyna_deck, then the model reader on the YAML,
/// whose messages name the deck's lines); `model.notes` holds the translation's notes. The
/// --set overrides use the keys of the translated model (`fpmshell convert` shows them).
[[nodiscard]] Model read_lsdyna_deck(const std::string& deck_path,
                                     const std::vector<std::string>& set_overrides = {});

}  // namespace fpmshell
