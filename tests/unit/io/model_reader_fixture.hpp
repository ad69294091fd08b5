// What the model reader's tests share (tests/unit/io/test_model_reader*.cpp): a folder per test,
// the smallest valid model, and the check that a model gives one InputError naming file, line
// and key.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/model_reader.hpp"

namespace fpmshell::test {

/// A fresh folder for the running test, removed at the end of the test.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = std::filesystem::temp_directory_path() /
                ("fpmshell_reader_" + std::string(info->name()) + "_" + std::to_string(::getpid()) +
                 "_" + std::to_string(counter_++));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    [[nodiscard]] std::string write(const std::string& name, const std::string& text) const {
        const auto p = path_ / name;
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    [[nodiscard]] std::string path(const std::string& name) const {
        return (path_ / name).string();
    }

private:
    static inline int counter_ = 0;
    std::filesystem::path path_;
};

// The smallest valid model; line numbers matter for the error tests below.
inline const std::string k_base = R"(title: t
mesh: {generator: plate, length_x: 2, length_y: 1, nx: 4, ny: 2}
materials:
  steel: {type: elastic, density: 7.8e-9, youngs_modulus: 210000, poisson_ratio: 0.3}
sections:
  - {elements: all, material: steel, thickness: 0.1}
control:
  end_time: 1.0e-3
)";

inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("test bug: '" + from + "' not in model");
    return text.replace(at, from.size(), to);
}

/// Reads `text` as model.yaml; expects an InputError starting with model.yaml:LINE (no line
/// when line == 0, any line when line < 0), key 'KEY' (when not empty) and `part`.
inline void expect_error(const std::string& text, int line, const std::string& key,
                         const std::string& part, const std::vector<std::string>& overrides = {}) {
    const TempDir dir;
    const std::string file = dir.write("model.yaml", text);
    try {
        (void)read_model(file, overrides);
        ADD_FAILURE() << "no error; expected one about key '" << key << "'";
    } catch (const InputError& e) {
        const std::string what = e.what();
        const std::string where = line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
        if (line >= 0) {
            EXPECT_EQ(what.rfind(where, 0), 0U) << what << "\n  expected start: " << where;
        } else {
            EXPECT_EQ(what.rfind(file + ":", 0), 0U) << what;
        }
        if (!key.empty()) {
            EXPECT_NE(what.find("key '" + key + "': "), std::string::npos) << what;
        }
        EXPECT_NE(what.find(part), std::string::npos) << what << "\n  expected: " << part;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
    }
}

/// Same for an error reported against an override ("--set: key 'KEY': ...").
inline void expect_override_error(const std::vector<std::string>& overrides, const std::string& key,
                                  const std::string& part) {
    const TempDir dir;
    try {
        (void)read_model(dir.write("model.yaml", k_base), overrides);
        ADD_FAILURE() << "no error for the override of '" << key << "'";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("--set: key '" + key + "': ", 0), 0U) << what;
        EXPECT_NE(what.find(part), std::string::npos) << what << "\n  expected: " << part;
    }
}

}  // namespace fpmshell::test
