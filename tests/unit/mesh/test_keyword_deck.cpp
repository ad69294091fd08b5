// Unit tests of the LS-DYNA keyword-file reader (mesh/keyword_deck.hpp): blocks, comments,
// parameters, formats and the cutting of fields.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/mesh/keyword_deck.hpp"

namespace fpmshell {
namespace {

std::string write_deck(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() /
                      ("fpmshell_keyword_deck_" + name + "_" + std::to_string(::getpid()) + ".k");
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

// Blocks keep their keyword (upper case, without the format suffix), file, line and data cards;
// comments are dropped; a blank line inside a block is a card of defaults (a part's heading may
// be blank, a weld's second card left blank), at its end too; *KEYWORD, *PARAMETER and *END make
// no block.
TEST(KeywordDeck, ReadsBlocksAndParameters) {
    const std::string path = write_deck("blocks", R"(*KEYWORD
$ a comment
*PARAMETER
R thick   0.002     I count   4
*title
Two blocks
*SECTION_SHELL+

                   1                   2
*Control_Termination
0.01

*END
*NODE
)");
    const KeywordDeck deck = read_keyword_deck(path);
    ASSERT_EQ(deck.blocks.size(), 3U);
    EXPECT_EQ(deck.blocks[0].keyword, "TITLE");
    EXPECT_EQ(deck.blocks[0].line, 5);
    EXPECT_EQ(deck.blocks[0].cards[0].text, "Two blocks");
    EXPECT_EQ(deck.blocks[1].keyword, "SECTION_SHELL");
    EXPECT_EQ(deck.blocks[1].format, DeckFormat::Long);
    ASSERT_EQ(deck.blocks[1].cards.size(), 2U);  // the blank line is a card of defaults
    EXPECT_TRUE(deck.blocks[1].cards[0].blank());
    EXPECT_EQ(deck.blocks[1].cards[1].line, 9);
    EXPECT_EQ(deck.blocks[2].keyword, "CONTROL_TERMINATION");
    EXPECT_EQ(deck.blocks[2].format, DeckFormat::Standard);
    ASSERT_EQ(deck.blocks[2].cards.size(), 2U);  // the blank line before *END: a card of defaults
    EXPECT_TRUE(deck.blocks[2].cards[1].blank());
    EXPECT_EQ(deck.parameters.at("THICK"), "R0.002");
    EXPECT_EQ(deck.parameters.at("COUNT"), "I4");
    std::filesystem::remove(path);
}

// Fields: commas split (free format), else fixed columns, 20 wide in the long format
// (*KEYWORD LONG=Y for every block after it, '+' for one).
TEST(KeywordDeck, CutsFieldsInEveryFormat) {
    DeckBlock standard{"X", "f.k", 1, DeckFormat::Standard, {}};
    DeckBlock wide{"X", "f.k", 1, DeckFormat::Long, {}};
    const DeckCard fixed{2, "         1       2.5         x"};
    EXPECT_EQ(deck_fields(standard, fixed, {10, 10, 10, 10}),
              (std::vector<std::string>{"1", "2.5", "x", ""}));
    const DeckCard free{2, " 1, 2.5 ,,x"};
    EXPECT_EQ(deck_fields(standard, free, {10, 10}),
              (std::vector<std::string>{"1", "2.5", "", "x"}));
    const DeckCard long_card{2, "                   1                 2.5"};
    EXPECT_EQ(deck_fields(wide, long_card, {10, 10}), (std::vector<std::string>{"1", "2.5"}));

    const std::string path =
        write_deck("long", "*KEYWORD LONG=Y\n*NODE\n1\n*KEYWORD LONG=S\n*PART\np\n");
    const KeywordDeck deck = read_keyword_deck(path);
    ASSERT_EQ(deck.blocks.size(), 2U);
    EXPECT_EQ(deck.blocks[0].format, DeckFormat::Long);
    EXPECT_EQ(deck.blocks[1].format, DeckFormat::Standard);
    std::filesystem::remove(path);
}

// Errors name the file and line: a card before any keyword, a parameter without a value, an
// included file that is not a regular file.
TEST(KeywordDeck, ReportsErrorsWithLines) {
    const auto expect_error = [](const std::string& name, const std::string& text,
                                 const std::string& where, const std::string& what) {
        const std::string path = write_deck(name, text);
        try {
            (void)read_keyword_deck(path);
            ADD_FAILURE() << "no error for " << name;
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(path + where), std::string::npos) << message;
            EXPECT_NE(message.find(what), std::string::npos) << message;
        }
        std::filesystem::remove(path);
    };
    expect_error("first", "1, 2, 3\n*NODE\n", ":1: ", "before the first keyword");
    expect_error("value", "*PARAMETER\nR thick\n", ":2: ", "has no value");
    expect_error("two", "*INCLUDE\n/dev/null\nother.k\n", ":2: ", "not a regular file");
}

}  // namespace
}  // namespace fpmshell
