// What the fuzz targets share (fuzz/README.md): a scratch folder for the files a reader opens,
// and the rule they check, that bad input ends in an InputError (exit 2) and nothing else.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "fpmshell/core/errors.hpp"

namespace fpmshell::fuzz {

/// A folder of this process's own under $TMPDIR (or /tmp), made at the first call and removed
/// at exit.
inline const std::filesystem::path& scratch_folder() {
    static const std::filesystem::path folder = [] {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern =
            std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/fpmshell-fuzz-XXXXXX";
        if (::mkdtemp(pattern.data()) == nullptr) {
            std::perror("fpmshell fuzz: cannot make a scratch folder");
            std::abort();
        }
        std::atexit([] {
            std::error_code ignored;
            std::filesystem::remove_all(scratch_folder(), ignored);
        });
        return std::filesystem::path(pattern);
    }();
    return folder;
}

/// Writes `size` bytes of `data` to `name` in the scratch folder and returns its path.
inline std::filesystem::path write_scratch_file(const std::string& name, const std::uint8_t* data,
                                                std::size_t size) {
    const std::filesystem::path path = scratch_folder() / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) {
        std::fprintf(stderr, "fpmshell fuzz: cannot write %s\n", path.c_str());
        std::abort();
    }
    return path;
}

/// Runs `read`, for which any input is allowed to end in one of the `Allowed` exceptions
/// (InputError for a reader; RunFailure too where the target runs steps). Any other exception
/// is a finding: it is printed and the process aborts, which libFuzzer reports as a crash.
template <class... Allowed, class Read>
void expect_only(Read&& read) {
    try {
        try {
            read();
        } catch (const InputError&) {
        }
    } catch (const std::exception& e) {
        if (((dynamic_cast<const Allowed*>(&e) != nullptr) || ...)) return;
        std::fprintf(stderr, "fpmshell fuzz: unexpected exception: %s\n", e.what());
        std::abort();
    }
}

}  // namespace fpmshell::fuzz
