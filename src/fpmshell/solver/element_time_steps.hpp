// The critical time step of every element (theory.md §6.4): the smaller of the membrane step
// L_c / c and the bending step of its own 9 x 9 eigenproblem (elements/bending_time_step.hpp),
// reduced for stiffness damping; the elements of a material that separates (§7.7), and those
// in a piece of one or two elements joined by their sides (in the mesh, or left so by erosion),
// take the isolated triangle's exact membrane step instead of L_c / c (eq. 6.4-3,
// elements/membrane_time_step.hpp).
// Both are kept as the step's ratio to L_c / c, which depends on the element's shape and h / L_c
// only: it is computed at set-up once per section and shape class and shared, and re-evaluated for
// an element whose L_c drifts.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// L_c = 2A / l_max of the triangle (p0, p1, p2) (§6.4).
[[nodiscard]] Real characteristic_length(const Vec3& p0, const Vec3& p1, const Vec3& p2);

/// Eq. 6.4-3: whether element e (live) is in a piece of at most two elements joined by their
/// sides, among the elements `live` says are (side_neighbour: MeshTopology's). Such a piece's
/// highest membrane mode exceeds 2 / (0.9 L_c / c) (tools/theory_checks/test_dt_pieces.py: a
/// lone equilateral triangle 2.18, two sharing a side 2.03, three in a row 1.96, a large patch
/// 1.87, as omega x 0.9 L_c / c).
template <class Live>
[[nodiscard]] bool in_small_piece(const std::vector<Index>& side_neighbour, Index e,
                                  const Live& live) {
    const auto live_neighbours = [&](Index f, Index& one) {
        int n = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            const Index g = side_neighbour[3 * static_cast<std::size_t>(f) + i];
            if (g >= 0 && live(g)) {
                ++n;
                one = g;
            }
        }
        return n;
    };
    Index other = -1, back = -1;
    const int n = live_neighbours(e, other);
    return n == 0 || (n == 1 && live_neighbours(other, back) == 1);
}

class ElementTimeSteps {
public:
    /// wave_speed, bending_rigidity: per section, c = sqrt(E / rho (1 - nu^2)) and
    /// D_b = (h^3 / 12) C (§4.1).
    ElementTimeSteps(const Model& model, const MeshTopology& topology, std::vector<Real> wave_speed,
                     std::vector<Mat3> bending_rigidity);

    /// Eq. 6.4-2: sqrt(min(1, V_0 / V)) of an element of initial volume v0 and current volume
    /// A h v, on one element or a pack of them (the same bits: div and sqrt round correctly).
    template <class T>
    [[nodiscard]] static T volume_factor(const T& v0, const T& v) {
        return sqrt(min(T(1.0), v0 / v));
    }
    /// A_0 h_0 of element e.
    [[nodiscard]] Real initial_volume(std::size_t e) const { return initial_volume_[e]; }
    /// Critical step of element e of current length lc and volume factor volume_factor(V_0, A h)
    /// (§6.4), unscaled. (Inline, as refresh: the element loop calls both for every element of
    /// every step.)
    [[nodiscard]] Real critical_dt(Index e, Real lc, Real volume_factor) const {
        return with_stiffness_damping(undamped_dt(e, lc, volume_factor));
    }
    /// critical_dt with §6.10's mass scaling during the run: an element whose step has fallen
    /// below the target of enable_run_scaling is given the step of the target, and its mass
    /// factor is kept for take_pending_scaling (element e only writes entry e: the element
    /// loop may call it from several threads). `scaled` counts the elements so given.
    [[nodiscard]] Real scaled_critical_dt(Index e, Real lc, Real volume_factor, Index& scaled) {
        Real dt = undamped_dt(e, lc, volume_factor);
        // eq. 6.10a (an element scaled already may be an ulp below the target: not again)
        if (dt < run_target_ * (1.0 - 1e-12) && dt > 0) {
            pending_[static_cast<std::size_t>(e)] = (run_target_ / dt) * (run_target_ / dt);
            dt = run_target_;
            ++scaled;
        }
        return with_stiffness_damping(dt);
    }
    /// Re-evaluates the step ratio of element e (corners t, positions x, current length lc)
    /// when lc has drifted by more than k_ratio_drift from the length the ratio was
    /// computed at.
    void refresh(Index e, const std::array<Index, 3>& t, const std::vector<Vec3>& x, Real lc) {
        const auto ue = static_cast<std::size_t>(e);
        if (!(lc > 0) || std::abs(lc - ratio_lc_[ue]) <= k_ratio_drift * ratio_lc_[ue]) return;
        reevaluate(e, t, x, lc);
    }
    /// The step ratio depends on the element shape and h / L_c only; it is
    /// re-evaluated (a 9x9 eigenproblem) when L_c has changed by more than this fraction since
    /// the last evaluation, which bounds the ratio's staleness to a few per cent of the step.
    static constexpr Real k_ratio_drift = 0.05;

    /// §6.10 mass scaling: per element, the factor f_e >= 1 on its mass and inertia shares
    /// that raises its critical step at the corners x to at least `step` (eq. 6.10a; 1 where
    /// it is there already).
    [[nodiscard]] std::vector<Real> mass_scaling_factors(
        Real step, const std::vector<std::array<Index, 3>>& triangles,
        const std::vector<Vec3>& x) const;
    /// Multiplies element e's mass and inertia shares by factor[e] (mass_scaling_factors): its
    /// membrane and bending steps grow by sqrt(factor[e]), the step ratio stays.
    void scale_masses(const std::vector<Real>& factor);
    /// §6.10 during the run: from now on scaled_critical_dt keeps every element's critical step
    /// at or above `step` (the run's target / time_step_scale).
    void enable_run_scaling(Real step);
    /// The mass and inertia added to one corner of an element by the scaling of a step.
    struct CornerAddition {
        Index element;
        Real mass, inertia;
    };
    /// Applies the mass factors scaled_critical_dt has kept since the last call to the elements'
    /// shares, and returns what each element's corners gained, in element order.
    [[nodiscard]] std::vector<CornerAddition> take_pending_scaling();

    /// The state of §6.10 carried from step to step (restart files): per element, its corner
    /// mass and inertia shares and sqrt(f_e).
    template <class Archive>
    void transfer_masses(Archive& ar) {
        ar(node_mass_, node_inertia_, mass_scale_);
    }

    /// Element e's share of that state: its corner mass and inertia and sqrt(f_e) (1 without
    /// scaling), and back (a distributed run's elements on rank 0).
    [[nodiscard]] std::array<Real, 3> mass_state(std::size_t e) const {
        return {node_mass_[e], node_inertia_[e], mass_scale_.empty() ? 1.0 : mass_scale_[e]};
    }
    void set_mass_state(std::size_t e, const std::array<Real, 3>& m) {
        node_mass_[e] = m[0];
        node_inertia_[e] = m[1];
        if (!mass_scale_.empty()) mass_scale_[e] = m[2];
    }

    /// Eq. 6.4-3 for element e from now on (an element left in a piece of one or two by the
    /// erosion of its neighbours): the flag, and its step ratio at its current corners t of x.
    void take_exact_membrane(Index e, const std::array<Index, 3>& t, const std::vector<Vec3>& x);
    /// The flag alone (a restart's or a separation's state brings the ratio).
    void mark_exact_membrane(Index e) { exact_element_[static_cast<std::size_t>(e)] = 1; }
    [[nodiscard]] bool exact_membrane(Index e) const {
        return exact_element_[static_cast<std::size_t>(e)] != 0 ||
               exact_membrane_[static_cast<std::size_t>(section_[static_cast<std::size_t>(e)])] !=
                   0;
    }

    /// The state carried from step to step (restart files): per element, the step ratio and
    /// the L_c it was evaluated at.
    std::vector<Real>& ratio() { return step_ratio_; }
    std::vector<Real>& ratio_length() { return ratio_lc_; }

private:
    /// Sets the step ratio of element e from its current corners.
    void reevaluate(Index e, const std::array<Index, 3>& t, const std::vector<Vec3>& x, Real lc);
    /// Element e's critical step / (L_c / c) at corners `corners`, where it is below 1 or
    /// the element's section takes the exact membrane step: the bending step's, and for such a
    /// section the smaller of it and the membrane step's (eq. 6.4-3).
    [[nodiscard]] Real step_ratio(Index e, const std::array<Vec3, 3>& corners) const;
    /// Multiplies element e's mass and inertia shares by f (§6.10): its steps grow by sqrt(f).
    void scale_element(std::size_t e, Real f);
    /// Sets every element's ratio at the initial geometry, shared within shape classes.
    void share_initial_ratios(const Model& model);
    /// The step of element e of length lc and volume factor (eq. 6.4-2) before the reduction
    /// for stiffness damping (§6.4).
    [[nodiscard]] Real undamped_dt(Index e, Real lc, Real volume_factor) const {
        const auto ue = static_cast<std::size_t>(e);
        // an element of a rigid section moves rigidly (§6.11): no step of its own
        if (rigid_section_[static_cast<std::size_t>(section_[ue])])
            return std::numeric_limits<Real>::infinity();
        // §6.4 membrane step L_c / c; the bending modes of thick elements (h / L_c > ~0.5) are
        // slower to integrate, and the separating elements' membrane (eq. 6.4-3): step_ratio_ < 1.
        // Eq. 6.4-2: the mass stays on the particles, so an element whose volume has grown past its
        // initial one (stretched with its thickness kept) is as dense as rho V_0 / (A h).
        Real dt = lc / wave_speed_[static_cast<std::size_t>(section_[ue])] *
                  std::min(std::min(Real{1}, step_ratio_[ue]), volume_factor);
        if (!mass_scale_.empty()) dt *= mass_scale_[ue];  // §6.10: sqrt(f_e)
        return dt;
    }
    /// §6.4: dt <= (2/w)(sqrt(1+xi^2) - xi), w = 2/dt
    [[nodiscard]] Real with_stiffness_damping(Real dt) const {
        if (stiffness_damping_ > 0) {
            const Real xi = stiffness_damping_ / dt;
            dt *= std::sqrt(1.0 + xi * xi) - xi;
        }
        return dt;
    }
    /// The undamped step that the damped critical step `step` needs (eq. 6.10a).
    [[nodiscard]] Real undamped_target(Real step) const;

    std::vector<Index> section_;               ///< per element
    std::vector<std::uint8_t> rigid_section_;  ///< per section: of a rigid material
    std::vector<Real> wave_speed_;             ///< per section
    std::vector<Mat3> bending_rigidity_;       ///< per section
    std::vector<Real> node_mass_,
        node_inertia_;                  ///< per element, its share at each corner (§6.1-6.2)
    std::vector<Real> initial_volume_;  ///< per element, A_0 h_0 (eq. 6.4-2)
    BendingKernel bending_kernel_ = BendingKernel::Dkt;
    Real stiffness_damping_ = 0;
    /// per section: its elements take the exact membrane step (a material that separates)
    std::vector<std::uint8_t> exact_membrane_;
    /// per element: it takes the exact membrane step, in a piece of one or two elements joined
    /// by their sides (in the mesh, or left so by erosion)
    std::vector<std::uint8_t> exact_element_;
    std::vector<Real> step_ratio_;  ///< per element, critical step / (L_c / c) (step_ratio)
    std::vector<Real> ratio_lc_;    ///< per element, the L_c step_ratio_ was evaluated at
    std::vector<Real> mass_scale_;  ///< per element, sqrt(f_e) of §6.10 (empty: no scaling)
    Real run_target_ = 0;           ///< §6.10 during the run: the undamped target step (0: off)
    std::vector<Real> pending_;     ///< per element, the factor scaled_critical_dt kept (0: none)
};

}  // namespace fpmshell
