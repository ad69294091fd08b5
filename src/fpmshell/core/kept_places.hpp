// Where a rank of a distributed run keeps the entries of an array it holds only in part (the
// state of the elements it computes, the slots it writes or receives): each kept entry at its
// place among the kept ones, in their order.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

namespace fpmshell {

/// The place of an entry a rank does not keep (never read there).
inline constexpr std::size_t k_not_kept = std::numeric_limits<std::size_t>::max();

struct KeptPlaces {
    std::vector<std::size_t> place;  ///< per entry: its place among the kept, or k_not_kept
    std::size_t count = 0;           ///< the entries kept
};

/// The places of n entries of which those with kept(i) are kept.
template <class Kept>
[[nodiscard]] KeptPlaces kept_places(std::size_t n, const Kept& kept) {
    KeptPlaces k;
    k.place.assign(n, k_not_kept);
    for (std::size_t i = 0; i < n; ++i)
        if (kept(i)) k.place[i] = k.count++;
    return k;
}

}  // namespace fpmshell
