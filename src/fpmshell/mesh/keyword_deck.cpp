// LS-DYNA keyword files into blocks (see keyword_deck.hpp).
#include "fpmshell/mesh/keyword_deck.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/text.hpp"
#include "fpmshell/mesh/deck_parameters.hpp"
#include "fpmshell/mesh/raw_mesh.hpp"

namespace fpmshell {
namespace {

using text_mesh::split_commas;
using text_mesh::upper;

class DeckReader {
public:
    KeywordDeck read(const std::string& path) {
        namespace fs = std::filesystem;
        main_folder_ = fs::path(path).parent_path();
        read_file(path, "", 0, 0);
        // includes not found where they stood: again with every *INCLUDE_PATH of the deck
        // (the deck may give its paths after the includes that need them)
        while (!deferred_.empty()) {
            const std::size_t before = deferred_.size();
            std::vector<Deferred> waiting;
            waiting.swap(deferred_);
            for (const Deferred& d : waiting) {
                if (const auto found = find_include(d.name, d.from); !found.empty())
                    read_file(found, d.from, d.line, d.depth);
                else
                    deferred_.push_back(d);
            }
            if (deferred_.size() == before) {
                const Deferred& d = deferred_.front();
                fail_at(
                    d.from, d.line,
                    "*INCLUDE: cannot open '" + d.name + "' (looked in " + looked_in(d.from) + ")");
            }
        }
        deck_.parameters = resolve_parameters(parameters_, duplication_, deck_.notes);
        return std::move(deck_);
    }

private:
    enum class Pending { None, Include, IncludePath, Parameter, Expression, Duplication };
    struct Deferred {
        std::string name, from;
        int line = 0, depth = 0;
    };

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
        Pending pending = Pending::None;
        bool local = false;  // the *PARAMETER being read is _LOCAL
        int include_at = 0;  // the line of an *INCLUDE whose file name is still to come
        std::string name;    // a file name continued on the next line (" +")
        std::string text;
        int number = 0;
        const auto close_include = [&] {
            if (include_at > 0)
                deck_.notes.push_back(
                    input_error_text(path, include_at, "", "*INCLUDE names no file: nothing read"));
            include_at = 0;
        };
        while (std::getline(in, text)) {
            ++number;
            if (!text.empty() && text.back() == '\r') text.pop_back();
            if (!text.empty() && text.front() == '$') continue;
            const bool blank = trim(text).empty();
            if (blank && (block == nullptr || pending != Pending::None)) continue;
            if (!blank && text.front() == '*') {
                close_include();
                const std::string keyword = start(text, path, number, block, local);
                pending = keyword == "INCLUDE"                 ? Pending::Include
                          : keyword == "INCLUDE_PATH"          ? Pending::IncludePath
                          : keyword == "PARAMETER"             ? Pending::Parameter
                          : keyword == "PARAMETER_EXPRESSION"  ? Pending::Expression
                          : keyword == "PARAMETER_DUPLICATION" ? Pending::Duplication
                                                               : Pending::None;
                if (pending == Pending::Include) include_at = number;
                if (keyword == "END") break;
                continue;
            }
            switch (pending) {
                case Pending::Include: {
                    std::string part = trim(text);
                    const bool continued =
                        part.size() > 2 && part.compare(part.size() - 2, 2, " +") == 0;
                    name += continued ? trim(part.substr(0, part.size() - 2)) : part;
                    if (continued) continue;
                    include_at = 0;
                    if (const auto found = find_include(name, path); !found.empty())
                        read_file(found, path, number, depth + 1);
                    else
                        deferred_.push_back({name, path, number, depth + 1});
                    name.clear();
                    continue;
                }
                case Pending::IncludePath:
                    include_paths_.push_back(trim(text));
                    continue;
                case Pending::Parameter:
                case Pending::Expression:
                    read_parameter_card(text, long_, pending == Pending::Expression, local, path,
                                        number, parameters_);
                    continue;
                case Pending::Duplication: {
                    long long flag = 0;
                    const std::string field = trim(text.substr(0, 10));
                    if (!text_mesh::parse_whole(field.empty() ? "1" : field, flag) || flag < 1 ||
                        flag > 5)
                        fail_at(path, number,
                                "*PARAMETER_DUPLICATION: DFLAG '" + field +
                                    "' should be 1, 2, 3, 4 or 5");
                    duplication_ = static_cast<ParameterDuplication>(flag);
                    continue;
                }
                case Pending::None:
                    break;
            }
            if (block == nullptr)
                fail_at(path, number, "a data card before the first keyword; expected *KEYWORD");
            block->cards.push_back({number, text});  // a blank card: every field its default
        }
        if (!name.empty())
            fail_at(path, number,
                    "*INCLUDE: the file name '" + name + "' goes on past the file's end (' +')");
        close_include();
        open_.pop_back();
    }

    /// Where an included file is: as given when absolute; else in the including file's
    /// folder, the main deck's, then each *INCLUDE_PATH folder read so far ("" if nowhere).
    std::string find_include(const std::string& name, const std::string& from) const {
        namespace fs = std::filesystem;
        std::error_code ec;
        const fs::path given(name);
        if (given.is_absolute()) return fs::exists(given, ec) ? name : "";
        for (const fs::path& folder : search_folders(from)) {
            const fs::path candidate = folder / given;
            if (fs::exists(candidate, ec)) return candidate.string();
        }
        return "";
    }

    std::vector<std::filesystem::path> search_folders(const std::string& from) const {
        std::vector<std::filesystem::path> folders{std::filesystem::path(from).parent_path(),
                                                   main_folder_};
        for (const std::string& p : include_paths_) {
            const std::filesystem::path folder(p);
            folders.push_back(folder.is_absolute() ? folder : main_folder_ / folder);
        }
        return folders;
    }

    std::string looked_in(const std::string& from) const {
        std::string s;
        for (const auto& f : search_folders(from))
            s += (s.empty() ? "'" : ", '") + (f.empty() ? std::string(".") : f.string()) + "'";
        return s;
    }

    /// Starts the block of a keyword line; returns the keyword, or for the keywords read here
    /// (no block is made) their family: INCLUDE, INCLUDE_PATH, PARAMETER, PARAMETER_EXPRESSION,
    /// PARAMETER_DUPLICATION. `local` tells a *PARAMETER(_EXPRESSION)_LOCAL.
    std::string start(const std::string& text, const std::string& path, int number,
                      DeckBlock*& block, bool& local) {
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
        local = false;
        if (name == "KEYWORD") {
            if (rest.find("LONG=Y") != std::string::npos) long_ = true;
            if (rest.find("LONG=S") != std::string::npos) long_ = false;
            return name;
        }
        if (name == "END" || name == "INCLUDE" || name == "PARAMETER_DUPLICATION") return name;
        if (name == "INCLUDE_PATH" || name == "INCLUDE_PATH_RELATIVE") return "INCLUDE_PATH";
        for (const char* family : {"PARAMETER_EXPRESSION", "PARAMETER"}) {
            const std::string f = family;
            for (const char* option : {"", "_NOECHO", "_LOCAL"})
                if (name == f + option) {
                    local = std::string(option) == "_LOCAL";
                    return f;
                }
        }
        if (name.rfind("INCLUDE", 0) == 0 || name.rfind("PARAMETER", 0) == 0)
            fail_at(path, number,
                    "*" + name +
                        " is not supported; fpmshell reads *INCLUDE (one or more files), "
                        "*INCLUDE_PATH(_RELATIVE), *PARAMETER, *PARAMETER_EXPRESSION (and their "
                        "_LOCAL and _NOECHO) and *PARAMETER_DUPLICATION");
        deck_.blocks.push_back({name, path, number, format, {}});
        block = &deck_.blocks.back();
        return name;
    }

    [[noreturn]] static void fail_at(const std::string& file, int line,
                                     const std::string& message) {
        throw InputError(input_error_text(file, line, "", message));
    }

    KeywordDeck deck_;
    std::vector<std::string> open_;  // the files being read, outermost first
    bool long_ = false;              // *KEYWORD LONG=Y
    int files_ = 0;                  // files opened so far
    std::filesystem::path main_folder_;
    std::vector<std::string> include_paths_;  // *INCLUDE_PATH folders, in reading order
    std::vector<Deferred> deferred_;          // includes not found yet
    std::vector<ParameterDefinition> parameters_;
    ParameterDuplication duplication_ = ParameterDuplication::WarnKeepFirst;
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
