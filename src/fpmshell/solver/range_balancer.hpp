// Ranges of the element loop sized by measured cost instead of block count. The element loop
// gives each thread one contiguous range of blocks (slot_gather_plan.hpp); equal counts leave a
// thread idle when the expensive blocks gather in one range, as the plastic folds of a crushed
// tube do near its struck end (perf: the second thread waited 37 % of the paper tube's folding
// phase, the first did every return mapping). The loop times its tiles; every
// k_steps_per_check steps the balancer cuts the blocks into ranges of equal measured time, when
// the current ranges are off by more than k_tolerated_imbalance. The ranges decide only which
// thread computes a block: the sums, and so the results, are the same bits for any ranges.
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

class RangeBalancer {
public:
    static constexpr int k_steps_per_check = 50;
    static constexpr double k_tolerated_imbalance = 1.05;  ///< slowest range / mean

    /// Blocks [first, end) took `seconds` this step (threads record disjoint blocks).
    void record(Index first, Index end, double seconds) {
        if (end <= first) return;
        if (block_seconds_.size() < static_cast<std::size_t>(end))
            return;  // sized by next_ranges before the first timed step
        const double each = seconds / static_cast<double>(end - first);
        for (Index b = first; b < end; ++b) block_seconds_[static_cast<std::size_t>(b)] += each;
    }

    /// Called once per step after the loop with the current range starts (ranges + 1 entries,
    /// the last the block count): new range starts every k_steps_per_check steps when the
    /// current ones are off balance by more than k_tolerated_imbalance, else nothing.
    [[nodiscard]] std::optional<std::vector<Index>> next_ranges(const std::vector<Index>& current) {
        const auto n_blocks = static_cast<std::size_t>(current.back());
        if (block_seconds_.size() != n_blocks) {
            block_seconds_.assign(n_blocks, 0.0);
            steps_ = 0;
            return std::nullopt;
        }
        if (++steps_ < k_steps_per_check) return std::nullopt;
        steps_ = 0;
        const std::size_t n_ranges = current.size() - 1;
        double total = 0, slowest = 0;
        for (std::size_t r = 0; r < n_ranges; ++r) {
            double range = 0;
            for (Index b = current[r]; b < current[r + 1]; ++b)
                range += block_seconds_[static_cast<std::size_t>(b)];
            total += range;
            slowest = std::max(slowest, range);
        }
        std::optional<std::vector<Index>> out;
        if (total > 0 && slowest * static_cast<double>(n_ranges) > k_tolerated_imbalance * total) {
            // range r starts at the first block whose preceding blocks hold r / n of the time
            std::vector<Index> begin(n_ranges + 1, 0);
            begin.back() = static_cast<Index>(n_blocks);
            double before = 0;
            std::size_t r = 1;
            for (std::size_t b = 0; b < n_blocks && r < n_ranges; ++b) {
                while (r < n_ranges &&
                       before >= total * static_cast<double>(r) / static_cast<double>(n_ranges))
                    begin[r++] = static_cast<Index>(b);
                before += block_seconds_[b];
            }
            for (; r < n_ranges; ++r) begin[r] = static_cast<Index>(n_blocks);
            if (begin != current) out = std::move(begin);
        }
        std::fill(block_seconds_.begin(), block_seconds_.end(), 0.0);
        return out;
    }

private:
    std::vector<double> block_seconds_;  ///< per block, since the last check
    int steps_ = 0;
};

}  // namespace fpmshell
