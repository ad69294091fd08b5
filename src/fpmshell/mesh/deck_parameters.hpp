// The parameters of an LS-DYNA deck: *PARAMETER values and *PARAMETER_EXPRESSION formulas,
// read from their cards anywhere in the deck and resolved once the whole deck is read (a
// formula may use a parameter defined after it), duplicates settled as *PARAMETER_DUPLICATION
// says. Formulas are evaluated by muParser (Debian's libmuparser-dev), LS-DYNA's notation
// first turned into muParser's: `**` is `^`, `&NAME` is `NAME`, names are case-insensitive.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace fpmshell {

/// One parameter as a card defines it.
struct ParameterDefinition {
    std::string name;  ///< upper case
    char type = 'R';   ///< R (real), I (integer) or C (characters)
    std::string text;  ///< the value, or the formula of an expression
    bool expression = false;
    bool local = false;  ///< _LOCAL: meant for its file and the files it includes
    std::string file;
    int line = 0;
};

/// Appends the definitions of one data card of *PARAMETER (pairs of "T name" and value, 10
/// columns each, 20 in the long format, or comma-separated) or, when `expression`, of
/// *PARAMETER_EXPRESSION ("T name" in 10 columns and the formula in the next 70; or the name,
/// a comma and the formula). Throws InputError "FILE:LINE: ..." for a malformed card.
void read_parameter_card(const std::string& text, bool long_format, bool expression, bool local,
                         const std::string& file, int line,
                         std::vector<ParameterDefinition>& definitions);

/// What *PARAMETER_DUPLICATION's DFLAG says of a name defined twice (LS-DYNA's default 1).
enum class ParameterDuplication {
    WarnKeepFirst = 1,
    WarnTakeLast = 2,
    KeepFirst = 3,
    TakeLast = 4,
    Refuse = 5
};

/// The value of every parameter by name: its type letter first, then its text (a formula's
/// value written as the shortest decimal that reads back the same; an integer's rounded to the
/// nearest whole number). Duplicates are settled by `duplication` in the order of
/// `definitions` (reading order); each warning goes into `notes` as "FILE:LINE: ...". Throws
/// InputError naming the card for a formula that does not parse, uses an unknown parameter
/// or itself, or whose value is not finite, and for a duplicate that `duplication` refuses.
[[nodiscard]] std::map<std::string, std::string> resolve_parameters(
    const std::vector<ParameterDefinition>& definitions, ParameterDuplication duplication,
    std::vector<std::string>& notes);

}  // namespace fpmshell
