// Warm start of the contact multipliers (theory.md §8.3a): the multipliers of the last step's
// constraints, by the constraint's identity (slave, masters, body), as the starting values of
// the projected Gauss-Seidel sweeps of the next step. A contact that persists carries nearly the
// same force from step to step, so the sweeps start next to their solution instead of at zero.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
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
        mark_slaves();
    }
    /// Whether a multiplier is kept for a constraint of slave `s` (most constraints have none:
    /// this spares them the search of recall).
    [[nodiscard]] bool has_slave(Index s) const {
        const auto us = static_cast<std::size_t>(s);
        return us < slave_kept_.size() && slave_kept_[us] != 0;
    }
    /// The multiplier kept for `key` (0: none).
    [[nodiscard]] Real recall(const Key& key) const {
        const auto it = std::lower_bound(entries_.begin(), entries_.end(), key,
                                         [](const auto& e, const Key& k) { return e.first < k; });
        return it != entries_.end() && it->first == key ? it->second : Real{0};
    }
    [[nodiscard]] std::size_t size() const { return entries_.size(); }

    /// The state carried from step to step (restart files). A loaded state is used once
    /// `restored` has accepted it.
    template <class Archive>
    void transfer(Archive& ar) {
        ar(entries_);
    }
    /// Whether the entries (as loaded from a restart file) are a memory of a model with
    /// `n_particles` particles and `n_bodies` rigid bodies: keys sorted and unique, a slave
    /// particle, master particles or -1, a body or -1, and finite positive multipliers. Then
    /// they are kept as the memory; otherwise it is emptied.
    [[nodiscard]] bool restored(Index n_particles, Index n_bodies) {
        auto within = [](Index i, Index lo, Index n) { return i >= lo && i < n; };
        bool valid = true;
        for (std::size_t k = 0; k < entries_.size() && valid; ++k) {
            const auto& [key, lambda] = entries_[k];
            valid = within(key[0], 0, n_particles) && within(key[1], -1, n_particles) &&
                    within(key[2], -1, n_particles) && within(key[3], -1, n_particles) &&
                    within(key[4], -1, n_bodies) && std::isfinite(lambda) && lambda > 0 &&
                    (k == 0 || entries_[k - 1].first < key);
        }
        if (!valid) entries_.clear();
        mark_slaves();
        return valid;
    }

private:
    /// slave_kept_ from entries_ (the flags of the last entries cleared first).
    void mark_slaves() {
        for (const Index s : marked_) slave_kept_[static_cast<std::size_t>(s)] = 0;
        marked_.clear();
        for (const auto& e : entries_) {
            const auto s = static_cast<std::size_t>(e.first[0]);
            if (s >= slave_kept_.size()) slave_kept_.resize(s + 1, 0);
            if (!slave_kept_[s]) marked_.push_back(e.first[0]);
            slave_kept_[s] = 1;
        }
    }

    std::vector<std::pair<Key, Real>> entries_;  ///< sorted by key, unique
    std::vector<std::uint8_t> slave_kept_;       ///< per particle: a slave of an entry
    std::vector<Index> marked_;                  ///< the particles flagged in slave_kept_
};

}  // namespace fpmshell
