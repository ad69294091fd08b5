// Tied surfaces (model-format.md `constraints` of type tied, theory.md §6.12; LS-DYNA's
// *CONTACT_TIED_NODES_TO_SURFACE, _SHELL_EDGE_TO_SURFACE, _SURFACE_TO_SURFACE): each tied
// particle (slave) keeps its place relative to the point sum xi_k x_k of the face it was found
// closest to at t = 0. Each step its velocity becomes that of the point, by equal and opposite
// impulses on it and on the face's corners (momentum conserved, no work on the tied motion),
// swept over the ties in their order until every tie holds.
#pragma once

#include <array>
#include <cstdint>
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
    /// impulse_time: c1 dt_n, over which the step's impulses J are the force J / impulse_time
    /// (new_step: the first call of a step; a second one, after the contact, adds to them). A
    /// tiebreak whose force reaches its criterion (eq. 6.12-2) lets go, after this call, for good.
    void impose(ParticleState& s, const BoundaryConditions& bc, Real impulse_time, bool new_step);

    /// Ties that have let go (tiebreaks, or their faces eroded).
    [[nodiscard]] std::size_t broken() const;
    /// §7.6: the ties to the faces of the elements `eroded` (sorted) let go for good, as
    /// LS-DYNA releases a tied node whose master segment is deleted.
    void release_eroded(const std::vector<Index>& eroded);
    /// Per tie, in tie order: its slave, and the force in tension and in shear at the last
    /// impose (0 for a broken tie).
    [[nodiscard]] std::vector<Index> slaves() const;
    /// The particles impose reads and moves: every tie's slave and its face's corners, sorted.
    [[nodiscard]] std::vector<Index> particles() const;
    [[nodiscard]] const std::vector<Real>& tension() const { return tension_; }
    [[nodiscard]] const std::vector<Real>& shear() const { return shear_; }

    /// The broken ties, for a restart file (io/restart_archive.hpp).
    template <class Archive>
    void transfer(Archive& ar) {
        ar(broken_);
    }
    /// Whether a loaded state fits these ties.
    [[nodiscard]] bool restored() const { return broken_.size() == ties_.size(); }

    static constexpr int k_max_sweeps = 200;

private:
    struct Tie {
        Index slave = -1;
        std::array<Index, 3> corner{};
        std::array<Real, 3> xi{};
        Index surface = -1;  ///< its entry of Model::tied_surfaces
        /// +1 / -1: the slave starts on the side of the face normal / against it; 0 on the face
        int side = 0;
        Real area = 0;    ///< the slave's area: a third of its triangles' at t = 0 (eq. 6.12-3)
        Index face = -1;  ///< the element whose face it is tied to
    };
    const Model* model_ = nullptr;
    std::vector<Tie> ties_;
    std::size_t untied_ = 0;
    std::vector<std::uint8_t> broken_;  ///< per tie
    std::vector<Vec3> impulse_;         ///< per tie: this step's (scratch)
    std::vector<Real> tension_, shear_;
};

}  // namespace fpmshell
