// LS-DYNA keyword files into blocks (see keyword_deck.hpp).
#include "fpmshell/mesh/keyword_deck.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/text.hpp"
#include "fpmshell/mesh/raw_mesh.hpp"

namespace fpmshell {
namespace {

using text_mesh::split_commas;
using text_mesh::upper;

class DeckReader {
public:
    KeywordDeck read(const std::string& path) {
        read_file(path, "", 0, 0);
        return std::move(deck_);
    }

private:
    void read_file(const std::string& path, const std::string& from, int from_line, int depth) {
        namespace fs = std::filesystem;
        std::error_code ec;
        const std::string canonical = fs::weakly_canonical(path, ec).string();
        if (std::find(open_.begin(), open_.end(), canonical) != open_.end())
            fail_at(from, from_line, "*INCLUDE: '" + path + "' includes itself (an include cycle)");
        if (depth > k_max_include_depth)
            fail_at(from, from_line,
                    "*INCLUDE: includes nest deeper than " + std::to_string(k_max_include_depth) +
                        " files");
        if (++files_ > k_max_deck_files)
            fail_at(from, from_line,
                    "*INCLUDE: the deck reads more than " + std::to_string(k_max_deck_files) +
                        " files");
        if (fs::exists(path, ec) && !fs::is_regular_file(path, ec))
            fail_at(
                from.empty() ? path : from, from_line,
                "cannot read '" + path + "': it is not a regular file; expected a keyword file");
        std::ifstream in(path, std::ios::binary);
        if (!in)
            fail_at(from.empty() ? path : from, from_line,
                    from.empty() ? "cannot open the keyword file"
                                 : "*INCLUDE: cannot open '" + path + "'");
        deck_.bytes += fs::file_size(path, ec);
        open_.push_back(canonical);
        DeckBlock* block = nullptr;  // the block the cards go to (null: before any keyword)
        enum class Pending { None, Include, Parameter, Done } pending = Pending::None;
        std::string text;
        int number = 0;
        while (std::getline(in, text)) {
            ++number;
            if (!text.empty() && text.back() == '\r') text.pop_back();
            if (!text.empty() && text.front() == '$') continue;
            const bool blank = trim(text).empty();
            if (blank && (block == nullptr || pending != Pending::None)) continue;
            if (!blank && text.front() == '*') {
                drop_trailing_blank_cards(block);
                const std::string keyword = start(text, path, number, block);
                pending = keyword == "INCLUDE"     ? Pending::Include
                          : keyword == "PARAMETER" ? Pending::Parameter
                                                   : Pending::None;
                if (keyword == "END") break;
                continue;
            }
            if (pending == Pending::Include) {
                const std::string name = trim(text);
                fs::path target(name);
                if (target.is_relative()) target = fs::path(path).parent_path() / target;
                read_file(target.string(), path, number, depth + 1);
                pending = Pending::Done;  // one file name per *INCLUDE
                continue;
            }
            if (pending == Pending::Parameter) {
                parameter(text, path, number);
                continue;
            }
            if (pending == Pending::Done)
                fail_at(path, number,
                        "*INCLUDE takes one file name; start another *INCLUDE for the next file");
            if (block == nullptr)
                fail_at(path, number, "a data card before the first keyword; expected *KEYWORD");
            block->cards.push_back({number, text});  // a blank card: every field its default
        }
        drop_trailing_blank_cards(block);
        open_.pop_back();
    }

    /// Blank lines at a block's end separate it from the next keyword; inside, a blank line is
    /// a card whose fields all take their defaults (a part's heading, a material's optional
    /// card), as LS-DYNA reads it.
    static void drop_trailing_blank_cards(DeckBlock* block) {
        while (block != nullptr && !block->cards.empty() && trim(block->cards.back().text).empty())
            block->cards.pop_back();
    }

    /// Starts the block of a keyword line; returns the keyword (blocks are not made for the
    /// keywords read here).
    std::string start(const std::string& text, const std::string& path, int number,
                      DeckBlock*& block) {
        std::string line = upper(trim(text.substr(1)));
        // the keyword ends at the first blank or comma (*KEYWORD may carry memory and LONG=)
        const auto end = line.find_first_of(" \t,");
        std::string name = line.substr(0, end);
        const std::string rest = end == std::string::npos ? "" : line.substr(end);
        DeckFormat format = long_ ? DeckFormat::Long : DeckFormat::Standard;
        if (!name.empty() && (name.back() == '+' || name.back() == '%' || name.back() == '-')) {
            format = name.back() == '+'   ? DeckFormat::Long
                     : name.back() == '%' ? DeckFormat::WideId
                                          : DeckFormat::Standard;
            name.pop_back();
        }
        block = nullptr;
        if (name == "KEYWORD") {
            if (rest.find("LONG=Y") != std::string::npos) long_ = true;
            if (rest.find("LONG=S") != std::string::npos) long_ = false;
            return name;
        }
        if (name == "END" || name == "INCLUDE" || name == "PARAMETER") return name;
        if (name.rfind("INCLUDE", 0) == 0 || name.rfind("PARAMETER", 0) == 0)
            fail_at(path, number,
                    "*" + name +
                        " is not supported; use *INCLUDE with a file name (relative to the "
                        "including file) and *PARAMETER with plain values");
        deck_.blocks.push_back({name, path, number, format, {}});
        block = &deck_.blocks.back();
        return name;
    }

    /// A *PARAMETER card: pairs of (type and name, value), 10 columns each, or free format.
    void parameter(const std::string& text, const std::string& path, int number) {
        std::vector<std::string> fields;
        if (text.find(',') != std::string::npos) {
            fields = split_commas(text);
        } else {
            for (std::size_t pos = 0; pos < text.size(); pos += 10)
                fields.push_back(trim(text.substr(pos, 10)));
        }
        for (std::size_t k = 0; k < fields.size(); k += 2) {
            const std::string& head = fields[k];
            if (head.empty()) continue;
            const char type = static_cast<char>(std::toupper(static_cast<unsigned char>(head[0])));
            const std::string name = upper(trim(head.substr(1)));
            if ((type != 'R' && type != 'I' && type != 'C') || name.empty())
                fail_at(path, number,
                        "*PARAMETER: '" + head +
                            "' should be a type R, I or C followed by the parameter's name");
            const std::string value = k + 1 < fields.size() ? fields[k + 1] : "";
            if (value.empty()) fail_at(path, number, "*PARAMETER: '" + name + "' has no value");
            deck_.parameters[name] = std::string(1, type) + value;
        }
    }

    [[noreturn]] static void fail_at(const std::string& file, int line,
                                     const std::string& message) {
        throw InputError(input_error_text(file, line, "", message));
    }

    KeywordDeck deck_;
    std::vector<std::string> open_;  // the files being read, outermost first
    bool long_ = false;              // *KEYWORD LONG=Y
    int files_ = 0;                  // files opened so far
};

}  // namespace

KeywordDeck read_keyword_deck(const std::string& path) { return DeckReader().read(path); }

std::vector<std::string> deck_fields(const DeckBlock& block, const DeckCard& card,
                                     const std::vector<std::size_t>& widths) {
    if (card.text.find(',') != std::string::npos) {
        std::vector<std::string> out = split_commas(card.text);
        out.resize(std::max(out.size(), widths.size()));
        return out;
    }
    std::vector<std::string> out;
    std::size_t pos = 0;
    for (const std::size_t standard : widths) {
        const std::size_t w = block.format == DeckFormat::Long ? 20 : standard;
        out.push_back(pos < card.text.size() ? trim(card.text.substr(pos, w)) : "");
        pos += w;
    }
    return out;
}

void deck_fail(const DeckBlock& block, int line, const std::string& message) {
    throw InputError(input_error_text(block.file, line, "", "*" + block.keyword + ": " + message));
}

}  // namespace fpmshell
