#include "fpmshell/io/restart_archive.hpp"

#include <fstream>
#include <sstream>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/atomic_file.hpp"

namespace fpmshell {
namespace {

constexpr char k_magic[8] = {'F', 'P', 'M', 'S', 'H', 'R', 'S', 'T'};
// Raised whenever the content of a restart file changes. A file of another format is refused:
// the sections of the solver, the elements and the result files are read only in the layout
// this build writes (format 5: the solver's section "mass_scaling", the masses mass scaling has
// added during the run; one section per result file, "history", "energy" and "fields").
constexpr std::uint32_t k_format_version = 5;

}  // namespace

RestartWriter::RestartWriter() {
    raw(k_magic, sizeof(k_magic));
    put(k_format_version);
    // Sizes of the raw types, so that a file from another build is refused, not misread.
    put(static_cast<std::uint8_t>(sizeof(double)));
    put(static_cast<std::uint8_t>(sizeof(long)));
    put(static_cast<std::uint8_t>(sizeof(int)));
}

void RestartWriter::save(const std::filesystem::path& path) const {
    write_file_atomic(path, bytes_);
}

RestartReader::RestartReader(const std::filesystem::path& path) : path_(path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("cannot open the restart file (is there a run to resume in this folder?)");
    std::ostringstream content;
    content << in.rdbuf();
    bytes_ = std::move(content).str();
    char magic[sizeof(k_magic)] = {};
    if (bytes_.size() < sizeof(k_magic) + 7 ||
        std::memcmp(bytes_.data(), k_magic, sizeof(k_magic)) != 0)
        fail("not an fpmshell restart file");
    pos_ = sizeof(magic);
    std::uint32_t version = 0;
    get(version);
    if (version < k_format_version)
        fail("restart file written by an earlier version of fpmshell (format " +
             std::to_string(version) + ", this version reads format " +
             std::to_string(k_format_version) +
             "): the run cannot be resumed with this version and must be restarted from the "
             "beginning "
             "(without --resume)");
    if (version > k_format_version)
        fail("restart file written by a later version of fpmshell (format " +
             std::to_string(version) + ", this version reads format " +
             std::to_string(k_format_version) + ")");
    format_ = version;
    std::uint8_t size_double = 0, size_long = 0, size_int = 0;
    get(size_double);
    get(size_long);
    get(size_int);
    if (size_double != sizeof(double) || size_long != sizeof(long) || size_int != sizeof(int))
        fail("restart file written by a build with other type sizes");
}

void RestartReader::raw(void* data, std::size_t n) {
    if (n > bytes_.size() - pos_) fail("restart file is truncated (in section '" + section_ + "')");
    if (n > 0) std::memcpy(data, bytes_.data() + pos_, n);
    pos_ += n;
}

std::size_t RestartReader::length() {
    std::uint64_t n = 0;
    get(n);
    if (n > bytes_.size() - pos_)
        fail("restart file is truncated or corrupt (in section '" + section_ + "')");
    return static_cast<std::size_t>(n);
}

void RestartReader::section(std::string_view name) {
    std::string found;
    get(found);
    if (found != name)
        fail("restart file is corrupt or from another version: expected section '" +
             std::string(name) + "', found '" + found + "'");
    section_ = std::string(name);
}

void RestartReader::finish() const {
    if (pos_ != bytes_.size())
        fail("restart file has unread bytes after section '" + section_ + "'");
}

void RestartReader::fail(const std::string& message) const {
    throw InputError(input_error_text(path_.string(), 0, "", message));
}

}  // namespace fpmshell
