// An LS-DYNA keyword file read into its keyword blocks: comments dropped, *INCLUDE files
// followed, *PARAMETER values collected, *END honoured; and the fields of a card cut out in the
// standard (fixed columns), long ('+', LONG=Y), wide-id ('%') or free (comma) format. The mesh
// reader (lsdyna_reader.cpp) and the deck translator (io/lsdyna_deck.cpp) both read decks
// through it.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace fpmshell {

/// How the fixed columns of a block are laid out.
enum class DeckFormat { Standard, Long, WideId };

/// One data card (a line that is neither a keyword nor a comment).
struct DeckCard {
    int line = 0;
    std::string text;
    /// A blank line: every field takes its default (lists of records skip it).
    [[nodiscard]] bool blank() const {
        return text.find_first_not_of(" \t\r") == std::string::npos;
    }
};

/// A keyword and its data cards, as written (one file: an *INCLUDE starts a block of its own).
struct DeckBlock {
    std::string keyword;  ///< upper case, without '*' and the format suffix: "SECTION_SHELL_TITLE"
    std::string file;
    int line = 0;
    DeckFormat format = DeckFormat::Standard;
    std::vector<DeckCard> cards;
};

struct KeywordDeck {
    std::vector<DeckBlock> blocks;  ///< in reading order, includes in place; no *INCLUDE,
                                    ///< *PARAMETER, *KEYWORD or *END blocks
    /// The parameters by upper-case name: the field text (a formula's value), its type (R, I
    /// or C) first (mesh/deck_parameters.hpp)
    std::map<std::string, std::string> parameters;
    std::vector<std::string> notes;  ///< "FILE:LINE: ..." for what was read otherwise than written
    std::uintmax_t bytes = 0;        ///< the size of every file read
};

/// Include depth beyond which a deck is refused (an include cycle is refused at once).
inline constexpr int k_max_include_depth = 16;
/// Files a deck may read in all (a file included many times over counts each time).
inline constexpr int k_max_deck_files = 4096;

/// Reads the deck at `path`. An *INCLUDE lists one or more files (a long name continued on the
/// next line after " +"), each found as given when absolute, else in the including file's
/// folder, the main deck's folder, then the folders of every *INCLUDE_PATH(_RELATIVE) of the
/// deck (wherever it stands; relative folders from the main deck's). *PARAMETER,
/// *PARAMETER_EXPRESSION (and _LOCAL, _NOECHO) and *PARAMETER_DUPLICATION are resolved once the
/// whole deck is read (deck_parameters.hpp). Throws InputError "FILE:LINE: ..." for a file that
/// cannot be read or is not a regular file, an include that cannot be found, nests too deep,
/// includes itself or makes the deck read more than k_max_deck_files files, a malformed
/// parameter, and an *INCLUDE_ or *PARAMETER_ form fpmshell does not read.
[[nodiscard]] KeywordDeck read_keyword_deck(const std::string& path);

/// The fields of `card`: split at commas when it has any (free format), else cut in columns
/// of `widths` (20 each in the long format). Fields are trimmed; missing ones are "".
[[nodiscard]] std::vector<std::string> deck_fields(const DeckBlock& block, const DeckCard& card,
                                                   const std::vector<std::size_t>& widths);

/// Throws InputError "FILE:LINE: *KEYWORD: message".
[[noreturn]] void deck_fail(const DeckBlock& block, int line, const std::string& message);

}  // namespace fpmshell
