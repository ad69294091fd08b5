// The parameters of an LS-DYNA deck (see deck_parameters.hpp).
#include "fpmshell/mesh/deck_parameters.hpp"

#include <fmt/format.h>
#include <muParser.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <set>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/text.hpp"
#include "fpmshell/mesh/raw_mesh.hpp"

namespace fpmshell {
namespace {

using text_mesh::upper;

[[noreturn]] void fail_at(const std::string& file, int line, const std::string& message) {
    throw InputError(input_error_text(file, line, "", message));
}

/// The type and name of a "T name" field ("R thick", "Rthick", "i  count").
void type_and_name(const std::string& head, const std::string& keyword, const std::string& file,
                   int line, ParameterDefinition& d) {
    const std::string h = trim(head);
    d.type = h.empty() ? ' ' : static_cast<char>(std::toupper(static_cast<unsigned char>(h[0])));
    d.name = h.empty() ? "" : upper(trim(h.substr(1)));
    if ((d.type != 'R' && d.type != 'I' && d.type != 'C') || d.name.empty())
        fail_at(
            file, line,
            keyword + ": '" + h + "' should be a type R, I or C followed by the parameter's name");
    if (d.name.find_first_of(" \t") != std::string::npos)
        fail_at(file, line,
                keyword + ": the parameter's name '" + d.name +
                    "' is not one word (the type and name take columns 1-10, the value follows)");
}

// LS-DYNA's functions that muParser does not have built in (it has sin ... atanh, log, log10,
// ln, exp, sqrt, abs, sign, rint, min, max, sum, avg)
double fn_mod(double a, double b) { return std::fmod(a, b); }
double fn_atan2(double y, double x) { return std::atan2(y, x); }
double fn_pow(double a, double b) { return std::pow(a, b); }
double fn_aint(double a) { return std::trunc(a); }
double fn_nint(double a) { return std::round(a); }

/// An LS-DYNA formula in muParser's notation: `**` is `^`, a D exponent is E, '&' before a
/// name is dropped, a name followed by '(' is a function (lower case), any other name a
/// parameter (upper case).
std::string muparser_notation(const std::string& formula) {
    std::string out;
    for (std::size_t i = 0; i < formula.size();) {
        const char c = formula[i];
        if (c == '*' && i + 1 < formula.size() && formula[i + 1] == '*') {
            out += '^';
            i += 2;
        } else if (c == '&') {
            ++i;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < formula.size() &&
                    std::isdigit(static_cast<unsigned char>(formula[i + 1])))) {
            // a number, its exponent included (1.5e-3, 1.5d-3)
            while (i < formula.size() &&
                   (std::isdigit(static_cast<unsigned char>(formula[i])) || formula[i] == '.'))
                out += formula[i++];
            if (i < formula.size() && std::strchr("eEdD", formula[i]) != nullptr) {
                out += 'e';
                ++i;
                if (i < formula.size() && (formula[i] == '+' || formula[i] == '-'))
                    out += formula[i++];
                while (i < formula.size() && std::isdigit(static_cast<unsigned char>(formula[i])))
                    out += formula[i++];
            }
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            std::string word;
            while (i < formula.size() &&
                   (std::isalnum(static_cast<unsigned char>(formula[i])) || formula[i] == '_'))
                word += formula[i++];
            std::size_t j = i;
            while (j < formula.size() && (formula[j] == ' ' || formula[j] == '\t')) ++j;
            const bool function = j < formula.size() && formula[j] == '(';
            if (function) {
                for (char& w : word)
                    w = static_cast<char>(std::tolower(static_cast<unsigned char>(w)));
                out += word;
            } else {
                out += upper(word);
            }
        } else {
            out += c;
            ++i;
        }
    }
    return out;
}

class Resolver {
public:
    explicit Resolver(std::map<std::string, const ParameterDefinition*> chosen)
        : chosen_(std::move(chosen)) {}

    std::map<std::string, std::string> values() {
        std::map<std::string, std::string> out;
        for (const auto& [name, d] : chosen_) {
            std::string value = text_of(*d);
            value.insert(value.begin(), d->type);  // the type letter first
            out[name] = std::move(value);
        }
        return out;
    }

private:
    /// The text a parameter's uses read: a value as written, a formula's value.
    std::string text_of(const ParameterDefinition& d) {
        if (!d.expression || d.type == 'C') return d.text;
        const double v = number(d);
        if (d.type == 'I') return fmt::format("{}", static_cast<long long>(std::llround(v)));
        return fmt::format("{}", v);
    }

    /// The number of a parameter (its formula evaluated once, its uses first).
    double number(const ParameterDefinition& d) {
        if (const auto it = numbers_.find(d.name); it != numbers_.end()) return it->second;
        if (!d.expression) {
            Real v = 0;
            if (!text_mesh::parse_real(d.text, v))
                fail_at(d.file, d.line,
                        "*PARAMETER: '" + d.name + "' = '" + d.text +
                            "' is not a number, so a formula cannot use it");
            return numbers_[d.name] = v;
        }
        if (!evaluating_.insert(d.name).second)
            fail_at(
                d.file, d.line,
                "*PARAMETER_EXPRESSION: '" + d.name + "' depends on itself through its formula");
        double value = 0;
        try {
            mu::Parser p;
            p.DefineFun("mod", fn_mod);
            p.DefineFun("atan2", fn_atan2);
            p.DefineFun("pow", fn_pow);
            p.DefineFun("aint", fn_aint);
            p.DefineFun("nint", fn_nint);
            p.SetExpr(muparser_notation(d.text));
            // the parameters it uses: their values first (any order of definition)
            std::map<std::string, double> uses;
            for (const auto& [name, unused] : p.GetUsedVar()) {
                (void)unused;
                const auto it = chosen_.find(name);
                if (it == chosen_.end())
                    fail_at(d.file, d.line,
                            "*PARAMETER_EXPRESSION: '" + d.name + "' uses '" + name +
                                "', which no *PARAMETER defines");
                uses[name] = number(*it->second);
            }
            for (auto& [name, v] : uses) p.DefineVar(name, &v);
            value = p.Eval();
        } catch (const mu::Parser::exception_type& e) {
            fail_at(d.file, d.line,
                    "*PARAMETER_EXPRESSION: the formula of '" + d.name + "' ('" + trim(d.text) +
                        "') does not read: " + e.GetMsg());
        }
        if (!std::isfinite(value))
            fail_at(d.file, d.line,
                    "*PARAMETER_EXPRESSION: the formula of '" + d.name + "' ('" + trim(d.text) +
                        "') is not a finite number");
        evaluating_.erase(d.name);
        return numbers_[d.name] = value;
    }

    std::map<std::string, const ParameterDefinition*> chosen_;
    std::map<std::string, double> numbers_;
    std::set<std::string> evaluating_;
};

}  // namespace

void read_parameter_card(const std::string& text, bool long_format, bool expression, bool local,
                         const std::string& file, int line,
                         std::vector<ParameterDefinition>& definitions) {
    const std::string keyword = expression ? "*PARAMETER_EXPRESSION" : "*PARAMETER";
    ParameterDefinition d;
    d.expression = expression;
    d.local = local;
    d.file = file;
    d.line = line;
    if (expression) {  // "T name" and the formula: a comma after the name, or columns 10 + 70
        const auto comma = text.find(',');
        const bool free = comma != std::string::npos && comma < 10 + 1 &&
                          text.substr(0, comma).find_first_not_of(" \t") != std::string::npos;
        type_and_name(free ? text.substr(0, comma) : text.substr(0, 10), keyword, file, line, d);
        d.text = trim(free ? text.substr(comma + 1) : (text.size() > 10 ? text.substr(10) : ""));
        if (d.text.empty()) fail_at(file, line, keyword + ": '" + d.name + "' has no formula");
        definitions.push_back(d);
        return;
    }
    std::vector<std::string> fields;
    if (text.find(',') != std::string::npos) {
        fields = text_mesh::split_commas(text);
    } else {
        const std::size_t w = long_format ? 20 : 10;
        for (std::size_t pos = 0; pos < text.size(); pos += w)
            fields.push_back(trim(text.substr(pos, w)));
    }
    for (std::size_t k = 0; k < fields.size(); k += 2) {
        if (fields[k].empty()) continue;
        type_and_name(fields[k], keyword, file, line, d);
        d.text = k + 1 < fields.size() ? fields[k + 1] : "";
        if (d.text.empty()) fail_at(file, line, keyword + ": '" + d.name + "' has no value");
        definitions.push_back(d);
    }
}

std::map<std::string, std::string> resolve_parameters(
    const std::vector<ParameterDefinition>& definitions, ParameterDuplication duplication,
    std::vector<std::string>& notes) {
    std::map<std::string, const ParameterDefinition*> chosen;
    for (const ParameterDefinition& d : definitions) {
        const auto [it, fresh] = chosen.try_emplace(d.name, &d);
        if (fresh) continue;
        const ParameterDefinition& first = *it->second;
        const std::string place = first.file + ":" + std::to_string(first.line);
        const bool same =
            first.text == d.text && first.type == d.type && first.expression == d.expression;
        if (same) continue;
        if ((first.local || d.local) || duplication == ParameterDuplication::Refuse)
            fail_at(d.file, d.line,
                    "parameter '" + d.name + "' is defined twice with other values (first at " +
                        place + ")" +
                        (first.local || d.local
                             ? "; fpmshell keeps one value per name, also for _LOCAL parameters"
                             : " and *PARAMETER_DUPLICATION DFLAG 5 refuses it"));
        const bool take_last = duplication == ParameterDuplication::WarnTakeLast ||
                               duplication == ParameterDuplication::TakeLast;
        if (duplication == ParameterDuplication::WarnKeepFirst ||
            duplication == ParameterDuplication::WarnTakeLast)
            notes.push_back(input_error_text(
                d.file, d.line, "",
                "*PARAMETER: '" + d.name + "' is defined again (first at " + place + "): the " +
                    (take_last ? "new value is taken" : "first value is kept") +
                    " (*PARAMETER_DUPLICATION DFLAG " +
                    std::to_string(static_cast<int>(duplication)) + ")"));
        if (take_last) it->second = &d;
    }
    return Resolver(std::move(chosen)).values();
}

}  // namespace fpmshell
