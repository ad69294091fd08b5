#include "fpmshell/io/restart_archive.hpp"

#include <zlib.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/atomic_file.hpp"

namespace fpmshell {
namespace {

constexpr char k_magic[8] = {'F', 'P', 'M', 'S', 'H', 'R', 'S', 'T'};
// Raised whenever the content of a restart file changes. A file of another format is refused:
// the sections of the solver, the elements and the result files are read only in the layout
// this build writes (format 7: the CRC-32 of the file's content at its end; the solver's
// section "mass_scaling", the masses mass scaling has added during the run; one section per
// result file, "history", "energy" and "fields"; the contact forces on each definition's
// slaves in the section "contact"; format 9: the elements' erosion state and the eroded
// internal energy; format 10: every material point as its law's numbers, the failure criteria's
// state; format 11: the solver's section "welds", the spot welds that have failed; format 12:
// the section "layout" first, the number of pieces of a distributed run's file and its step).
constexpr std::uint32_t k_format_version = 13;

/// Bytes of the checksum at the end of the file: the CRC-32 (zlib's, little-endian) of every
/// byte before it. It turns a file damaged after it was written (cut short, a flipped bit, an
/// edit) into a refusal, where the sections' names and lengths alone would let a changed number
/// through.
constexpr std::size_t k_checksum_bytes = 4;

std::uint32_t checksum(std::string_view bytes) {
    uLong crc = ::crc32_z(0L, nullptr, 0);
    return static_cast<std::uint32_t>(
        ::crc32_z(crc, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

std::string checksum_bytes(std::uint32_t crc) {
    std::string out(k_checksum_bytes, '\0');
    for (std::size_t i = 0; i < k_checksum_bytes; ++i)
        out[i] = static_cast<char>((crc >> (8 * i)) & 0xffu);
    return out;
}

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
    // the file's pieces in order, written and checksummed where they lie (no copy of a piece)
    std::vector<std::string_view> pieces;
    std::size_t at = 0;
    for (const Block& block : blocks_) {
        pieces.emplace_back(bytes_.data() + at, block.place - at);
        pieces.emplace_back(block.bytes);
        at = block.place;
    }
    pieces.emplace_back(bytes_.data() + at, bytes_.size() - at);
    uLong crc = ::crc32_z(0L, nullptr, 0);
    for (const std::string_view piece : pieces)
        crc = ::crc32_z(crc, reinterpret_cast<const Bytef*>(piece.data()), piece.size());
    const std::string tail = checksum_bytes(static_cast<std::uint32_t>(crc));
    pieces.emplace_back(tail);
    write_file_atomic(path, pieces);
}

std::string RestartWriter::with_checksum(std::string_view content) {
    return std::string(content) + checksum_bytes(checksum(content));
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
    const std::string_view checked(bytes_.data(),
                                   bytes_.size() - std::min(bytes_.size(), k_checksum_bytes));
    if (bytes_.size() < pos_ + k_checksum_bytes ||
        bytes_.compare(checked.size(), k_checksum_bytes, checksum_bytes(checksum(checked))) != 0)
        fail(
            "restart file is damaged: its checksum does not match its content (it was cut short "
            "or changed after it was written)");
    bytes_.resize(checked.size());
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

void RestartReader::flag(bool& v) {
    std::uint8_t byte = 0;
    raw(&byte, 1);
    if (byte > 1)
        fail("restart file is corrupt: a flag is neither 0 nor 1 (in section '" + section_ + "')");
    v = byte == 1;
}

std::size_t RestartReader::length(std::size_t item_bytes) {
    std::uint64_t n = 0;
    get(n);
    if (n > (bytes_.size() - pos_) / std::max<std::size_t>(item_bytes, 1))
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
