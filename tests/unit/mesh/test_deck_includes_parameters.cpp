// *INCLUDE and *PARAMETER as real decks write them (mesh/keyword_deck.hpp,
// mesh/deck_parameters.hpp): several files on one *INCLUDE, a long name continued with " +", an
// *INCLUDE with no file, *INCLUDE_PATH given after the includes that need it; formulas of
// *PARAMETER_EXPRESSION using parameters defined anywhere, LS-DYNA's notation (**, &NAME,
// functions), integers rounded; duplicates as *PARAMETER_DUPLICATION says.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/mesh/keyword_deck.hpp"

namespace fpmshell {
namespace {

namespace fs = std::filesystem;

class DeckFolder {
public:
    DeckFolder()
        : root_(fs::temp_directory_path() /
                ("fpmshell_deck_folder_" +
                 std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                 "_" + std::to_string(::getpid()))) {
        fs::create_directories(root_);
    }
    ~DeckFolder() { fs::remove_all(root_); }
    DeckFolder(const DeckFolder&) = delete;
    DeckFolder& operator=(const DeckFolder&) = delete;
    std::string write(const std::string& name, const std::string& text) const {
        const fs::path path = root_ / name;
        fs::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary) << text;
        return path.string();
    }

private:
    fs::path root_;
};

std::vector<std::string> keywords(const KeywordDeck& deck) {
    std::vector<std::string> out;
    for (const DeckBlock& b : deck.blocks) out.push_back(b.keyword);
    return out;
}

TEST(DeckIncludes, ReadSeveralFilesContinuedNamesAndPathsGivenLater) {
    const DeckFolder dir;
    dir.write("parts/a.k", "*PART\n");
    dir.write("parts/b.k", "*SECTION_SHELL\n");
    dir.write("lib/a_rather_long_file_name_for_the_materials.k", "*MAT_ELASTIC\n");
    dir.write("lib/curves.k", "*DEFINE_CURVE\n");
    const std::string main = dir.write("main.k",
                                       "*KEYWORD\n"
                                       "*INCLUDE\n"
                                       "parts/a.k\n"
                                       "parts/b.k\n"
                                       "*INCLUDE\n"
                                       "a_rather_long_file_name_ +\n"
                                       "for_the_materials.k\n"
                                       "*INCLUDE\n"
                                       "*INCLUDE\n"
                                       "curves.k\n"
                                       "*INCLUDE_PATH_RELATIVE\n"
                                       "lib\n"
                                       "*END\n");
    const KeywordDeck deck = read_keyword_deck(main);
    EXPECT_EQ(keywords(deck),
              (std::vector<std::string>{"PART", "SECTION_SHELL", "MAT_ELASTIC", "DEFINE_CURVE"}));
    ASSERT_EQ(deck.notes.size(), 1U);  // the *INCLUDE with no file
    EXPECT_NE(deck.notes[0].find("main.k:8: *INCLUDE names no file"), std::string::npos)
        << deck.notes[0];
}

TEST(DeckIncludes, AFileFoundNowhereNamesWhereItWasLookedFor) {
    const DeckFolder dir;
    const std::string main =
        dir.write("main.k", "*KEYWORD\n*INCLUDE\nabsent.k\n*INCLUDE_PATH\nlib\n");
    try {
        (void)read_keyword_deck(main);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("main.k:3: *INCLUDE: cannot open 'absent.k' (looked in"),
                  std::string::npos)
            << m;
        EXPECT_NE(m.find("lib'"), std::string::npos) << m;
    }
}

TEST(DeckParameters, FormulasUseParametersDefinedAnywhere) {
    const DeckFolder dir;
    dir.write("values.k", "*PARAMETER\nR t         0.002\n");
    const std::string main = dir.write("main.k",
                                       "*KEYWORD\n"
                                       "*PARAMETER_EXPRESSION\n"
                                       "R area    &t**2 * 1.5e+3\n"
                                       "R hyp     sqrt(3.0**2 + 4.0**2) + max(1, T)\n"
                                       "I count   2.0*RATIO\n"
                                       "R mixed   MOD(7, 4) + atan2(0, 1)\n"
                                       "R ratio, 0.5 * 2.8\n"
                                       "*INCLUDE\n"
                                       "values.k\n");
    const KeywordDeck deck = read_keyword_deck(main);
    EXPECT_EQ(deck.parameters.at("T"), "R0.002");
    EXPECT_EQ(deck.parameters.at("AREA"), "R0.006");
    EXPECT_EQ(deck.parameters.at("HYP"), "R6");
    EXPECT_EQ(deck.parameters.at("RATIO"), "R1.4");
    EXPECT_EQ(deck.parameters.at("COUNT"), "I3");  // 2.8 rounded
    EXPECT_EQ(deck.parameters.at("MIXED"), "R3");
}

TEST(DeckParameters, BadFormulasNameTheirCard) {
    const DeckFolder dir;
    const auto expect_error = [&](const std::string& name, const std::string& cards,
                                  const std::string& line, const std::string& what) {
        const std::string path =
            dir.write(name + ".k", "*KEYWORD\n*PARAMETER_EXPRESSION\n" + cards);
        try {
            (void)read_keyword_deck(path);
            ADD_FAILURE() << "no error for " << name;
        } catch (const InputError& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find(path + line + " *PARAMETER_EXPRESSION: "), std::string::npos) << m;
            EXPECT_NE(m.find(what), std::string::npos) << m;
        }
    };
    expect_error("unknown", "R a       1.0\nR b       a + c\n",
                 ":4:", "uses 'C', which no *PARAMETER");
    expect_error("cycle", "R a       b\nR b       a + 1\n", ":3:", "depends on itself");
    expect_error("syntax", "R a       1.0\nR b       (a + \n", ":4:", "does not read");
    expect_error("infinite", "R a       0.0\nR b       1 / a\n", ":4:", "not a finite number");
}

TEST(DeckParameters, DuplicatesAsParameterDuplicationSays) {
    const DeckFolder dir;
    const std::string cards = "*PARAMETER\nR t         1.0\n*PARAMETER\nR t         2.0\n";
    // LS-DYNA's default (DFLAG 1): the first value kept, with a note
    const KeywordDeck plain = read_keyword_deck(dir.write("plain.k", "*KEYWORD\n" + cards));
    EXPECT_EQ(plain.parameters.at("T"), "R1.0");
    ASSERT_EQ(plain.notes.size(), 1U);
    EXPECT_NE(plain.notes[0].find("plain.k:5: *PARAMETER: 'T' is defined again"), std::string::npos)
        << plain.notes[0];
    // the card may stand after the definitions it rules
    const KeywordDeck last = read_keyword_deck(
        dir.write("last.k", "*KEYWORD\n" + cards + "*PARAMETER_DUPLICATION\n         4\n"));
    EXPECT_EQ(last.parameters.at("T"), "R2.0");
    EXPECT_TRUE(last.notes.empty());
    EXPECT_THROW((void)read_keyword_deck(dir.write(
                     "refused.k", "*KEYWORD\n*PARAMETER_DUPLICATION\n         5\n" + cards)),
                 InputError);
    // the same value twice is no duplicate
    const KeywordDeck same = read_keyword_deck(dir.write(
        "same.k", "*KEYWORD\n*PARAMETER\nR t         1.0\n*PARAMETER\nR t         1.0\n"));
    EXPECT_TRUE(same.notes.empty());
}

}  // namespace
}  // namespace fpmshell
