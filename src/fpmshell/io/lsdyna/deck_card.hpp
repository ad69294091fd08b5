// The fields of an LS-DYNA card and the text helpers of the deck translator
// (lsdyna/deck_translator.hpp): parameters substituted, each field named in its message, and
// numbers and names written as the YAML model writes them.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "fpmshell/core/text.hpp"
#include "fpmshell/core/types.hpp"
#include "fpmshell/mesh/keyword_deck.hpp"
#include "fpmshell/mesh/lsdyna_reader.hpp"
#include "fpmshell/mesh/raw_mesh.hpp"

namespace fpmshell::deck {

using text_mesh::upper;

/// The fields of one card with the deck's parameters substituted; each accessor names the
/// field (LS-DYNA's own name) in its message.
class Card {
public:
    Card(const KeywordDeck& deck, const DeckBlock& block, const DeckCard& card,
         const std::vector<std::size_t>& widths)
        : deck_(deck), block_(block), line_(card.line), fields_(deck_fields(block, card, widths)) {}
    /// A blank field is `fallback`.
    [[nodiscard]] Real real(std::size_t k, const char* name, Real fallback = 0) const {
        const std::string f = value(k);
        if (f.empty()) return fallback;
        Real v = 0;
        if (!text_mesh::parse_real(f, v))
            fail(std::string(name) + " '" + f + "' is not a finite number");
        return v;
    }
    [[nodiscard]] long long id(std::size_t k, const char* name, long long fallback = 0) const {
        const std::string f = value(k);
        if (f.empty()) return fallback;
        long long v = 0;
        Real r = 0;
        if (text_mesh::parse_id(f, v)) return v;
        if (text_mesh::parse_real(f, r) && r == std::round(r) && std::abs(r) < 1e15)
            return static_cast<long long>(r);  // "5." in a real-looking column
        fail(std::string(name) + " '" + f + "' is not a whole number");
    }
    [[nodiscard]] std::string text(std::size_t k) const { return value(k); }
    [[nodiscard]] std::size_t size() const { return fields_.size(); }
    [[nodiscard]] int line() const { return line_; }
    [[nodiscard]] const DeckBlock& block() const { return block_; }
    [[noreturn]] void fail(const std::string& message) const { deck_fail(block_, line_, message); }

private:
    /// The field, or the value of the parameter it names (&NAME, -&NAME).
    [[nodiscard]] std::string value(std::size_t k) const {
        if (k >= fields_.size()) return "";
        const std::string& f = fields_[k];
        const bool negative = f.rfind("-&", 0) == 0;
        if (f.empty() || (f[0] != '&' && !negative)) return f;
        const std::string name = upper(f.substr(negative ? 2 : 1));
        const auto it = deck_.parameters.find(name);
        if (it == deck_.parameters.end())
            fail("parameter '" + name + "' is not defined by a *PARAMETER card");
        const std::string v = it->second.substr(1);
        if (!negative) return v;
        return v.rfind('-', 0) == 0 ? v.substr(1) : "-" + v;
    }

    const KeywordDeck& deck_;
    const DeckBlock& block_;
    int line_;
    std::vector<std::string> fields_;
};

inline const std::vector<std::size_t> k_ten(8, 10);  // the usual card: 8 fields of 10 columns

/// A number as the model file writes it (shortest round-trip form).
inline std::string num(Real v) { return fmt::format("{}", v); }
inline std::string vec(Real x, Real y, Real z) {
    return fmt::format("[{}, {}, {}]", x, y, z);  // each as num() writes it
}

/// A negative NUMFIP or NUMINT (field k of c, `name`), -value per cent of the layers through the
/// thickness that erode a shell, as `layer_fraction: f` (below -100 refused).
inline std::string layer_fraction_key(const Card& c, std::size_t k, const char* name) {
    const Real percent = -c.real(k, name);
    if (percent > 100) c.fail(std::string(name) + " must be at least -100 (every layer)");
    return "layer_fraction: " + num(percent / 100);
}

/// A YAML scalar for a name: plain when it is a word, else double-quoted.
inline std::string yaml_name(const std::string& s) {
    const bool plain = !s.empty() &&
                       std::all_of(s.begin(), s.end(),
                                   [](char c) {
                                       return std::isalnum(static_cast<unsigned char>(c)) ||
                                              c == '_' || c == '-' || c == '.';
                                   }) &&
                       !std::isdigit(static_cast<unsigned char>(s[0])) && s[0] != '-' &&
                       s[0] != '.';
    if (plain) return s;
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
    return out + "\"";
}

/// The option words of a keyword after its base: ("RIGIDWALL_PLANAR_MOVING_ID", 2) -> MOVING, ID.
inline std::set<std::string> options_of(const std::string& keyword, std::size_t base_words) {
    std::set<std::string> out;
    std::size_t pos = 0;
    for (std::size_t k = 0; k < base_words && pos != std::string::npos; ++k) {
        pos = keyword.find('_', pos);
        if (pos != std::string::npos) ++pos;
    }
    while (pos != std::string::npos && pos < keyword.size()) {
        const auto u = keyword.find('_', pos);
        out.insert(keyword.substr(pos, u == std::string::npos ? std::string::npos : u - pos));
        pos = u == std::string::npos ? u : u + 1;
    }
    return out;
}

inline bool starts_with(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

}  // namespace fpmshell::deck
