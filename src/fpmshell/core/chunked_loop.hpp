// Deterministic parallel loops over particles: results bitwise the same for any
// number of threads. The range is cut into chunks of a fixed size that does not
// depend on the thread count; a sum is the ordered sum of the per-chunk partial sums, each
// accumulated in index order, so it never depends on how OpenMP shares the chunks out.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// Particles per chunk: large enough that a chunk outweighs its scheduling (a chunk of the
/// particle update takes ~25 us), small enough to share the 5 000 particles of a 10^4-element
/// model evenly between a few threads (chunks of 1 024 split them 3 : 2 on two threads).
inline constexpr Index k_chunk_size = 256;

/// Runs body(i, sums) for i in [0, n) and returns the N sums the body accumulates into
/// `sums` (a std::array<Real, N> it receives zeroed per chunk). The body must touch only
/// index i's data besides `sums`. scratch: per-chunk partial sums, reused between calls.
template <int N, class Body>
std::array<Real, N> chunked_sum(Index n, [[maybe_unused]] bool parallel,
                                std::vector<std::array<Real, N>>& scratch, Body&& body) {
    const Index n_chunks = (n + k_chunk_size - 1) / k_chunk_size;
    scratch.resize(static_cast<std::size_t>(n_chunks));
#pragma omp parallel for schedule(static) if (parallel)
    for (Index c = 0; c < n_chunks; ++c) {
        std::array<Real, N> sums{};
        const Index end = std::min(n, (c + 1) * k_chunk_size);
        for (Index i = c * k_chunk_size; i < end; ++i) body(i, sums);
        scratch[static_cast<std::size_t>(c)] = sums;
    }
    std::array<Real, N> total{};
    for (const auto& part : scratch)
        for (std::size_t k = 0; k < total.size(); ++k) total[k] += part[k];
    return total;
}

/// Runs body(i) for i in [0, n), in parallel when asked; the body must touch only index i's data.
template <class Body>
void parallel_for_each(Index n, [[maybe_unused]] bool parallel, Body&& body) {
#pragma omp parallel for schedule(static) if (parallel)
    for (Index i = 0; i < n; ++i) body(i);
}

}  // namespace fpmshell
