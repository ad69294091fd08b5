// Error types that map onto the exit codes of the user contract (model-format.md):
// InputError -> exit 2 (the model or a file it names is invalid),
// RunFailure -> exit 1 (the run diverged; the last good state is on disk).
#pragma once

#include <stdexcept>
#include <string>

namespace fpmshell {

/// Invalid model or mesh. The message is one sentence naming file, line (when known) and key.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Builds the standard "FILE:LINE: key 'KEY': MESSAGE" sentence of every input error.
/// line <= 0 means "no line" (for example a problem found after parsing).
inline std::string input_error_text(const std::string& file, int line, const std::string& key,
                                    const std::string& message) {
    std::string where = file;
    if (line > 0) where.append(":").append(std::to_string(line));
    if (!key.empty()) return where + ": key '" + key + "': " + message;
    return where + ": " + message;
}

/// A place in an input file, for messages (line <= 0: none).
struct SourceLine {
    std::string file;
    int line = 0;
    std::string card;  ///< what is written there, when it is not a model key ("*MAT_ELASTIC")
};

/// A run that cannot continue (NaN, instability, energy blow-up, inverted element).
class RunFailure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace fpmshell
