// Erosion (theory.md §7.6): when an element of a section whose material can fail stops acting.
// Its failure criteria (failure/*.hpp) tell which of its points have failed; the rule counts
// them: by default the element erodes once every point through the thickness at one of its
// in-plane points has failed (LS-DYNA's rule for its shells of one in-plane point), or, with
// `points: N` (LS-DYNA's NUMFIP), once N of its points have.
#pragma once

#include "fpmshell/core/types.hpp"
#include "fpmshell/failure/plastic_strain_failure.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

class ElementErosion {
public:
    /// The rule of a material (inactive where it cannot fail) on a rule of n_inplane x
    /// n_through points, in-plane major.
    ElementErosion(const MaterialFailure& failure, int n_inplane, int n_through);

    [[nodiscard]] bool active() const { return active_; }
    /// Whether an element erodes, from the plastic strain of each of its points
    /// (plastic_strain(point), in-plane major).
    template <class PlasticStrain>
    [[nodiscard]] bool erodes(const PlasticStrain& plastic_strain) const {
        if (!active_) return false;
        int failed = 0;
        for (int g = 0; g < n_inplane_; ++g) {
            int failed_here = 0;
            for (int k = 0; k < n_through_; ++k)
                if (plastic_strain_.failed(
                        plastic_strain(static_cast<std::size_t>(g * n_through_ + k))))
                    ++failed_here;
            failed += failed_here;
            if (points_ == 0 && failed_here == n_through_) return true;
        }
        return points_ > 0 && failed >= points_;
    }

private:
    bool active_ = false;
    PlasticStrainFailure plastic_strain_;
    int points_ = 0;  ///< failed points that erode it; 0: one in-plane point's every point
    int n_inplane_ = 0, n_through_ = 0;
};

/// Whether some section of the model is of a material that can fail (its results then carry
/// the erosion's columns and fields).
[[nodiscard]] inline bool model_can_erode(const Model& model) {
    for (const Section& sec : model.sections)
        if (model.materials[static_cast<std::size_t>(sec.material)].failure.active()) return true;
    return false;
}

}  // namespace fpmshell
