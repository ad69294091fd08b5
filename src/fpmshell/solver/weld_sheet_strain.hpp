// The plastic strain of the sheets at the particles of the spot welds that fail by it (LS-DYNA's
// *CONSTRAINED_SPOTWELD EP and *CONSTRAINED_GENERALIZED_WELD_SPOT EPSF; theory.md eq. 6.11-15):
// a weld tears out of the sheet when the material around it has yielded far enough. The
// elements' plastic strains, each averaged over its points, are projected onto the particles by
// a least-squares fit with the lumped (row-sum) matrix of linear triangles: each particle's value
// is the area-weighted mean of its elements'.
#pragma once

#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct MeshTopology;
class RankExchange;
class ShellElements;

class WeldSheetStrain {
public:
    WeldSheetStrain() = default;
    /// The particles of the model's welds with a `plastic_strain` failure, and the elements
    /// around each of them (the topology's).
    WeldSheetStrain(const Model& model, const MeshTopology& topology);

    [[nodiscard]] bool empty() const { return particles_.empty(); }
    /// The particles followed, ascending.
    [[nodiscard]] const std::vector<Index>& particles() const { return particles_; }

    /// Eq. 6.11-15 from the elements' state at the end of the step: every particle followed
    /// gets the area-weighted mean of its elements' plastic strains. On several ranks each
    /// rank gives the elements it computes and the ranks join them in element order, so every
    /// rank gets the single process's values (collective).
    void update(const ShellElements& elements, const RankExchange& ranks);
    /// The value of particle p at the last update (0 for a particle not followed).
    [[nodiscard]] Real at(Index p) const;

private:
    std::vector<Index> particles_;            ///< ascending
    std::vector<std::size_t> first_;          ///< per particle followed, its first element; + end
    std::vector<std::size_t> element_place_;  ///< per (particle, element), its place in elements_
    std::vector<Index> elements_;             ///< the elements around them, ascending
    std::vector<Real> area_;                  ///< per element of elements_, its initial area
    std::vector<Real> value_;                 ///< per particle followed, at the last update
};

}  // namespace fpmshell
