// An archive in memory with the restart files' interface (restart_archive.hpp's
// transfer_value): what one object's transfer writes into it, another object's transfer of the
// same layout reads back. The solver hands its state to the solver of the mesh after a
// particle separation (theory.md §7.7) through it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

#include "fpmshell/io/restart_archive.hpp"

namespace fpmshell {

class MemoryArchive {
public:
    /// Writes (before rewind) or reads (after) every value in order.
    template <class... T>
    void operator()(T&... values) {
        (transfer_value(*this, values), ...);
    }
    void section(std::string_view /*name*/) {}
    /// From writing to reading, from the first byte.
    void rewind() {
        reading_ = true;
        at_ = 0;
    }

    void raw(void* data, std::size_t n) {
        if (!reading_) {
            bytes_.append(static_cast<const char*>(data), n);
            return;
        }
        if (at_ + n > bytes_.size()) throw std::logic_error("memory archive read past its end");
        std::memcpy(data, bytes_.data() + at_, n);
        at_ += n;
    }
    void flag(bool& v) {
        char c = v ? '\1' : '\0';
        raw(&c, 1);
        v = c != '\0';
    }
    template <class Sequence>
    void transfer_length(Sequence& v) {
        auto n = static_cast<std::uint64_t>(v.size());
        raw(&n, sizeof n);
        if (reading_) v.resize(static_cast<std::size_t>(n));
    }

private:
    std::string bytes_;
    std::size_t at_ = 0;
    bool reading_ = false;
};

}  // namespace fpmshell
