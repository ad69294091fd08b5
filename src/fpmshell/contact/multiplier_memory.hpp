// Warm start of the contact multipliers (theory.md §8.3a): the multipliers of the last step's
// constraints, by the constraint's identity (slave, masters, body), as the starting values of
// the projected Gauss-Seidel sweeps of the next step. A contact that persists carries nearly the
// same force from step to step, so the sweeps start next to their solution instead of at zero.
#pragma once

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

class MultiplierMemory {
public:
    /// What identifies a constraint from step to step: the slave particle, the three master
    /// particles (-1 for a rigid face) and the rigid body (-1 for a self-contact pair).
    using Key = std::array<Index, 5>;

    /// Forgets the last step's multipliers and keeps these (the positive ones), given as
    /// (key, lambda) in any order; equal keys keep the first given. `entries` is taken over and
    /// given back holding the old buffer (cleared), for the next step to fill without
    /// allocating.
    void keep(std::vector<std::pair<Key, Real>>& entries) {
        std::erase_if(entries, [](const auto& e) { return !(e.second > 0); });
        std::stable_sort(entries.begin(), entries.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        entries.erase(std::unique(entries.begin(), entries.end(),
                                  [](const auto& a, const auto& b) { return a.first == b.first; }),
                      entries.end());
        entries_.swap(entries);
        entries.clear();
    }
    /// The multiplier kept for `key` (0: none).
    [[nodiscard]] Real recall(const Key& key) const {
        const auto it = std::lower_bound(entries_.begin(), entries_.end(), key,
                                         [](const auto& e, const Key& k) { return e.first < k; });
        return it != entries_.end() && it->first == key ? it->second : Real{0};
    }
    [[nodiscard]] std::size_t size() const { return entries_.size(); }

    /// The state carried from step to step (restart files).
    template <class Archive>
    void transfer(Archive& ar) {
        ar(entries_);
    }

private:
    std::vector<std::pair<Key, Real>> entries_;  ///< sorted by key, unique
};

}  // namespace fpmshell
