// LS-DYNA keyword deck -> YAML model (see lsdyna_deck.hpp); the translation itself is
// io/lsdyna/deck_translator.hpp.
#include "fpmshell/io/lsdyna_deck.hpp"

#include <filesystem>

#include "fpmshell/core/text.hpp"
#include "fpmshell/io/lsdyna/deck_translator.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/mesh/raw_mesh.hpp"

namespace fpmshell {

bool is_keyword_deck(const std::string& path) {
    const std::string ext = text_mesh::upper(std::filesystem::path(path).extension().string());
    return ext == ".K" || ext == ".KEY" || ext == ".DYN" || ext == ".KW";
}

DeckTranslation translate_lsdyna_deck(const std::string& deck_path, const std::string& mesh_file) {
    return deck::DeckTranslator(deck_path, mesh_file).translate();
}

Model read_lsdyna_deck(const std::string& deck_path,
                       const std::vector<std::string>& set_overrides) {
    DeckTranslation t =
        translate_lsdyna_deck(deck_path, std::filesystem::path(deck_path).filename().string());
    Model model = read_model_text(t.yaml, std::move(t.origins), deck_path, set_overrides);
    // the translator's notes, then the model reader's (on the model the deck became)
    t.notes.insert(t.notes.end(), model.notes.begin(), model.notes.end());
    model.notes = std::move(t.notes);
    return model;
}

}  // namespace fpmshell
