// A disk that fills up, for the fault tests (fault_test.py). Preloaded into fpmshell
// (LD_PRELOAD), it lets the program write FPMSHELL_FULL_DISK_BYTES bytes in all to files under
// the folder FPMSHELL_FULL_DISK_DIR and then fails write() and writev() there with ENOSPC, as a
// file system that has run out of space does (a write that does not fit writes what fits).
// Every result file of fpmshell is written with write() (io/atomic_file.cpp) or through
// std::ofstream, which calls write() and writev().
#include <dlfcn.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <string>

namespace {

std::atomic<long long> g_written{0};

/// Whether descriptor fd is a file under FPMSHELL_FULL_DISK_DIR.
bool on_full_disk(int fd) {
    const char* dir = std::getenv("FPMSHELL_FULL_DISK_DIR");
    if (dir == nullptr || *dir == '\0') return false;
    char target[4096];
    const std::string link = "/proc/self/fd/" + std::to_string(fd);
    const ssize_t n = ::readlink(link.c_str(), target, sizeof target - 1);
    if (n <= 0) return false;
    return std::string(target, static_cast<std::size_t>(n)).rfind(dir, 0) == 0;
}

/// The bytes the disk still takes.
long long space_left() {
    const char* bytes = std::getenv("FPMSHELL_FULL_DISK_BYTES");
    const long long capacity = bytes != nullptr ? std::atoll(bytes) : 0;
    return std::max(0LL, capacity - g_written.load());
}

template <class F>
F real(const char* name) {
    return reinterpret_cast<F>(::dlsym(RTLD_NEXT, name));
}

}  // namespace

extern "C" ssize_t write(int fd, const void* data, size_t n) {
    static const auto real_write = real<ssize_t (*)(int, const void*, size_t)>("write");
    if (n > 0 && on_full_disk(fd)) {
        const long long left = space_left();
        if (left == 0) {
            errno = ENOSPC;
            return -1;
        }
        n = std::min<size_t>(n, static_cast<size_t>(left));
        const ssize_t done = real_write(fd, data, n);
        if (done > 0) g_written += done;
        return done;
    }
    return real_write(fd, data, n);
}

extern "C" ssize_t writev(int fd, const struct iovec* iov, int count) {
    static const auto real_writev = real<ssize_t (*)(int, const struct iovec*, int)>("writev");
    if (!on_full_disk(fd)) return real_writev(fd, iov, count);
    // the buffers one by one through write(), which stops where the disk is full
    ssize_t total = 0;
    for (int i = 0; i < count; ++i) {
        const ssize_t done = write(fd, iov[i].iov_base, iov[i].iov_len);
        if (done < 0) return total > 0 ? total : -1;
        total += done;
        if (static_cast<size_t>(done) < iov[i].iov_len) break;
    }
    return total;
}
