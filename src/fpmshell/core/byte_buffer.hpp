// Values of fixed size copied into and out of a byte buffer: the state a rank of a distributed
// run writes into its piece of a restart file (RankExchange::owned_particle_records,
// ShellElements::pack_state). The pieces are read back by the same build, so the layout is that
// of memory, without conversion.
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

namespace fpmshell {

/// Appends the bytes of v.
template <class T>
void append_bytes(std::vector<char>& bytes, const T& v) {
    const char* p = reinterpret_cast<const char*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(T));
}

/// Copies the bytes at `at` into v and moves `at` past them.
template <class T>
void read_bytes(const std::vector<char>& bytes, std::size_t& at, T& v) {
    std::memcpy(static_cast<void*>(&v), bytes.data() + at, sizeof(T));
    at += sizeof(T);
}

}  // namespace fpmshell
