// Write-to-temporary-then-rename. POSIX calls are used (not std::ofstream) so that every failure
// can be reported with the system's reason (errno), which is what a user needs to act on
// ("No space left on device", "Permission denied").
#include "fpmshell/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace fpmshell {

namespace {

std::string errno_text(int err) { return std::strerror(err); }

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, int err) {
    throw std::runtime_error("cannot write '" + path.string() + "': " + what + " (" +
                             errno_text(err) + ").");
}

}  // namespace

std::filesystem::path atomic_temp_path(const std::filesystem::path& path) {
    std::filesystem::path tmp = path;
    tmp += ".tmp." + std::to_string(static_cast<long>(::getpid()));
    return tmp;
}

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
    write_file_atomic(path, std::span<const std::string_view>(&content, 1));
}

void write_file_atomic(const std::filesystem::path& path,
                       std::span<const std::string_view> pieces) {
    const std::filesystem::path tmp = atomic_temp_path(path);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail(path, "creating the temporary file '" + tmp.string() + "' failed", errno);

    for (const std::string_view piece : pieces) {
        const char* data = piece.data();
        std::size_t left = piece.size();
        while (left > 0) {
            const ssize_t n = ::write(fd, data, left);
            if (n < 0) {
                if (errno == EINTR) continue;
                const int err = errno;
                ::close(fd);
                ::unlink(tmp.c_str());
                fail(path, "writing the temporary file failed", err);
            }
            data += n;
            left -= static_cast<std::size_t>(n);
        }
    }
    // No fsync: the guarantee is against a killed process, not a power cut, and fsync on every
    // history flush would cost more than the time step it records.
    if (::close(fd) != 0) {
        const int err = errno;
        ::unlink(tmp.c_str());
        fail(path, "closing the temporary file failed", err);
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmp.c_str());
        fail(path, "renaming the temporary file over it failed", err);
    }
}

}  // namespace fpmshell
