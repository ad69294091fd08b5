// summary.json's `plastic_strain` (model-format.md): the peak equivalent plastic strain of every
// surface over the elements, the largest and where it is. On several ranks each rank takes the
// elements it computes and the ranks reduce their peaks, so that no rank needs the others'
// elements and the answer is that of a single process, ties included.
#pragma once

#include <array>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

class ExplicitSolver;

struct PlasticStrainPeaks {
    /// Per surface (bottom, middle, top): the peak, and the lowest element that reaches it
    /// (-1 where the peak is 0).
    std::array<Real, 3> peak{};
    std::array<Index, 3> element{-1, -1, -1};
    /// The largest peak (the first surface of bottom, middle, top that reaches it; -1: none).
    [[nodiscard]] int surface() const;
};

/// The peaks of the solver's elements (on several ranks collective: every rank gets the
/// peaks over all ranks).
[[nodiscard]] PlasticStrainPeaks plastic_strain_peaks(const ExplicitSolver& solver);

}  // namespace fpmshell
