// The critical time step of every element (theory.md §6.4): the smaller of the membrane step
// L_c / c and the bending step of its own 9 x 9 eigenproblem (elements/bending_time_step.hpp),
// reduced for stiffness damping. The bending step is kept as its ratio to L_c / c, which
// depends on the element's shape and h / L_c only: it is computed at set-up once per section
// and shape class and shared, and re-evaluated for an element whose L_c drifts.
#pragma once

#include <array>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// L_c = 2A / l_max of the triangle (p0, p1, p2) (§6.4).
[[nodiscard]] Real characteristic_length(const Vec3& p0, const Vec3& p1, const Vec3& p2);

class ElementTimeSteps {
public:
    /// wave_speed, bending_rigidity: per section, c = sqrt(E / rho (1 - nu^2)) and
    /// D_b = (h^3 / 12) C (§4.1).
    ElementTimeSteps(const Model& model, const MeshTopology& topology, std::vector<Real> wave_speed,
                     std::vector<Mat3> bending_rigidity);

    /// Critical step of element e of current length lc (§6.4), unscaled.
    [[nodiscard]] Real critical_dt(Index e, Real lc) const;
    /// Re-evaluates the bending ratio of element e (corners t, positions x, current length lc)
    /// when lc has drifted from the length the ratio was computed at.
    void refresh(Index e, const std::array<Index, 3>& t, const std::vector<Vec3>& x, Real lc);

    /// The state carried from step to step (restart files): per element, the bending ratio and
    /// the L_c it was evaluated at.
    std::vector<Real>& ratio() { return bend_ratio_; }
    std::vector<Real>& ratio_length() { return bend_lc_; }

private:
    /// Bending critical step / (L_c / c) of element e at corners `corners`.
    [[nodiscard]] Real bending_ratio(Index e, const std::array<Vec3, 3>& corners) const;
    /// Sets every element's ratio at the initial geometry, shared within shape classes.
    void share_initial_ratios(const Model& model);

    std::vector<Index> section_;          ///< per element
    std::vector<Real> wave_speed_;        ///< per section
    std::vector<Mat3> bending_rigidity_;  ///< per section
    std::vector<Real> node_mass_,
        node_inertia_;  ///< per element, its share at each corner (§6.1-6.2)
    BendingKernel bending_kernel_ = BendingKernel::Dkt;
    Real stiffness_damping_ = 0;
    std::vector<Real> bend_ratio_;  ///< per element, bending critical step / (L_c / c)
    std::vector<Real> bend_lc_;     ///< per element, the L_c bend_ratio_ was evaluated at
};

}  // namespace fpmshell
