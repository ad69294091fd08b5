// String helpers shared by the readers of text input (the model file, --set, mesh files).
#pragma once

#include <string>
#include <string_view>

namespace fpmshell {

/// `s` without its leading and trailing `blanks` (by default spaces, tabs and line ends).
[[nodiscard]] inline std::string trim(const std::string& s, std::string_view blanks = " \t\r\n") {
    const auto begin = s.find_first_not_of(blanks);
    if (begin == std::string::npos) return "";
    const auto end = s.find_last_not_of(blanks);
    return s.substr(begin, end - begin + 1);
}

}  // namespace fpmshell
