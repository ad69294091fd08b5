// Tied surfaces (model-format.md `constraints` of type tied, theory.md §6.12; LS-DYNA's
// *CONTACT_TIED_NODES_TO_SURFACE, _SHELL_EDGE_TO_SURFACE, _SURFACE_TO_SURFACE): each tied
// particle (slave) keeps its place relative to the point sum xi_k x_k of the face it was found
// closest to at t = 0. Each step its velocity becomes that of the point, by equal and opposite
// impulses on it and on the face's corners (momentum conserved, no work on the tied motion),
// swept over the ties in their order until every tie holds.
#pragma once

#include <array>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct ParticleState;
class BoundaryConditions;

class TiedSurfaces {
public:
    /// The ties of the model's `constraints` of type tied: for each slave, the closest face of
    /// its entry's elements (not one of its own) within the tolerance (default: the larger of
    /// the particle's and the face's thickness); slaves with none stay free (counted).
    TiedSurfaces(const Model& model, const std::vector<Real>& element_thickness);

    [[nodiscard]] bool empty() const { return ties_.empty(); }
    [[nodiscard]] std::size_t tied() const { return ties_.size(); }
    /// Slaves with no face within the tolerance, over all entries (left free).
    [[nodiscard]] std::size_t untied() const { return untied_; }

    /// v^{n+1/2} of every slave becomes sum xi_k v_k of its face (eq. 6.12-1), by impulses J on
    /// the slave and -xi_k J on the corners, in the free directions of each (fixed and
    /// prescribed components take none); Gauss-Seidel sweeps in the ties' order until the
    /// largest mismatch is below 1e-13 of the largest velocity, at most k_max_sweeps.
    void impose(ParticleState& s, const BoundaryConditions& bc) const;

    static constexpr int k_max_sweeps = 200;

private:
    struct Tie {
        Index slave = -1;
        std::array<Index, 3> corner{};
        std::array<Real, 3> xi{};
    };
    std::vector<Tie> ties_;
    std::size_t untied_ = 0;
};

}  // namespace fpmshell
