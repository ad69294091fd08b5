// The element loop: every triangle of the model, its section rule, material and material
// points, and the deterministic assembly of element corner loads into particles
// (element-corner slots + ordered gather through a particle->slot CSR map, style.md §4).
#pragma once

#include <array>
#include <limits>
#include <utility>
#include <variant>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/elements/elastic_triangle_block.hpp"
#include "fpmshell/elements/shell_triangle.hpp"
#include "fpmshell/materials/section_material.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/particle_state.hpp"
#include "fpmshell/solver/slot_gather_plan.hpp"

namespace fpmshell {

class RestartWriter;
class RestartReader;

class ShellElements {
public:
    explicit ShellElements(const Model& model);

    struct StepTotals {
        Real strain_work = 0;     ///< sum of element strain work over the step
        Real damping_work = 0;    ///< sum of viscous work over the step
        Real plastic_work = 0;    ///< sum of plastic dissipation over the step (in strain_work)
        Real min_dt = 0;          ///< smallest element critical step at t_n (§6.4), unscaled
        Index min_dt_element = -1;
        Index failed_element = -1;  ///< first degenerate or flipped element, -1 if none
    };

    /// Internal forces and moments at t_n from the path element (x_prev, x, dtheta); writes
    /// s.f_int, s.m_int and updates the material points. viscous_rate = a_s / dt_{n-1/2};
    /// dt = dt_{n-1/2} for rate-dependent materials (0 in relaxation: no rate effects).
    StepTotals compute(ParticleState& s, Real viscous_rate, Real dt);

    /// Critical step of every element from the current geometry (§6.4), unscaled, minimum.
    [[nodiscard]] Real min_critical_dt(const std::vector<Vec3>& x, Index* where = nullptr) const;
    /// Critical step of element e at positions x (§6.4), unscaled.
    [[nodiscard]] Real critical_dt(Index e, const std::vector<Vec3>& x) const { return element_dt(e, current_length(e, x)); }

    [[nodiscard]] Index size() const { return static_cast<Index>(tri_.size()); }
    /// Membrane force N and bending moment M of element e averaged over the element, in its
    /// local frame, at the end of the last step.
    [[nodiscard]] Voigt3 membrane_force(Index e) const { return resultant(static_cast<std::size_t>(e), 0); }
    [[nodiscard]] Voigt3 bending_moment(Index e) const { return resultant(static_cast<std::size_t>(e), 3); }
    /// Equivalent plastic strain of element e averaged over its in-plane points, at the
    /// thickness point of index k (0 = bottom, n-1 = top).
    [[nodiscard]] Real plastic_strain(Index e, int k) const;
    [[nodiscard]] int thickness_points(Index e) const {
        return static_cast<int>(rules_[static_cast<std::size_t>(section_[static_cast<std::size_t>(e)])].through.size());
    }
    /// Current thickness of element e (the section's, or updated by §3.4).
    [[nodiscard]] Real thickness(Index e) const { return thickness_[static_cast<std::size_t>(e)]; }

    /// The state carried from step to step (material points, thickness, bending step ratios,
    /// resultants), for a restart file (io/restart_archive.hpp).
    void save(RestartWriter& out) const;
    void load(RestartReader& in);

private:
    /// What the step totals need of a group of elements (a block, an element computed alone,
    /// a chunk of them): its works, its smallest critical step and the lowest-numbered element
    /// with it, the lowest-numbered failed element (-1: none).
    struct ElementTotals {
        Real strain_work = 0, damping_work = 0, plastic_work = 0;
        Real dt = std::numeric_limits<Real>::infinity();
        Index dt_element = -1, failed = -1;
        void add(const ElementTotals& o);  ///< o's works added after this one's
    };
    /// Critical step of element e of current length lc: the smaller of the membrane step L_c / c and
    /// the bending step (the stored ratio bend_ratio_ times L_c / c), reduced for stiffness
    /// damping (§6.4).
    [[nodiscard]] Real element_dt(Index e, Real lc) const;
    /// L_c = 2A / l_max of element e at positions x (§6.4).
    [[nodiscard]] Real current_length(Index e, const std::vector<Vec3>& x) const;
    /// Re-evaluates bend_ratio_[e] when lc (its current L_c) has drifted from the length the
    /// ratio was computed at.
    void refresh_bending_ratio(Index e, const std::vector<Vec3>& x, Real lc);
    [[nodiscard]] Real bending_ratio(Index e, const std::vector<Vec3>& x) const;
    /// Path element of element e (§2).
    [[nodiscard]] ReversedTriangle reverse_element(std::size_t e, const ParticleState& s) const;
    /// Phase 1 of compute for one element by the general (scalar) code.
    /// Its totals: see ElementTotals.
    [[nodiscard]] ElementTotals compute_element(Index e, ParticleState& s, Real viscous_rate, Real dt);
    /// Phase 1 of compute for the k_lanes elements of SIMD block b (lanes outside the block
    /// kernel's bounds go to compute_element). Its corner loads go to ring_slots (the block's
    /// place in a ring of slot_gather_plan.hpp; nullptr: none) and, where the plan keeps the
    /// block or there is no ring, to slot_loads_.
    void compute_block(Index b, ParticleState& s, Real viscous_rate, Real dt, Real* ring_slots);
    /// Sums the slots of particle p (in element order) into s.f_int, s.m_int; base: the ring
    /// or slot_loads_, which gather_plan_.offset points into.
    void gather_particle(std::size_t p, const Real* base, ParticleState& s) const;
    /// Integration points of element e.
    [[nodiscard]] std::size_t n_points_of(std::size_t e) const;
    /// Fields of a point of element e in the block layout: the stress only (elastic section,
    /// k_stress_fields) or the whole history (J2, k_j2_fields).
    [[nodiscard]] std::size_t point_fields(std::size_t e) const;
    /// The state of point p of element e, wherever it is kept (an elastic point: its stress);
    /// and its update.
    [[nodiscard]] MaterialPoint point_state(std::size_t e, std::size_t p) const;
    void set_point_state(std::size_t e, std::size_t p, const MaterialPoint& mp);
    // The fields of a point in the block layout (block_state_), one pack each.
    static constexpr std::size_t k_stress = 0, k_back_stress = 3, k_plastic_strain = 6, k_plastic_work = 7,
                                 k_strain_rate = 8, k_flow_radius = 9, k_flow_slope = 10;
    static constexpr std::size_t k_stress_fields = 3, k_j2_fields = 11;

    std::vector<std::array<Index, 3>> tri_;
    std::vector<Index> section_;               ///< per element
    std::vector<ShellRule> rules_;             ///< per section
    std::vector<SectionMaterial> materials_;   ///< per section
    std::vector<Real> wave_speed_;             ///< per section, c = sqrt(E / rho (1 - nu^2))
    std::vector<Mat3> bending_rigidity_;       ///< per section, D_b = (h^3 / 12) C (§4.1)
    std::vector<Real> node_mass_, node_inertia_;  ///< per element, its share at each node (§6.1-6.2)
    std::vector<Real> thickness_;   ///< per element, current h
    bool thickness_update_ = false;
    std::vector<Real> bend_ratio_;  ///< per element, bending critical step / (L_c / c)
    std::vector<Real> bend_lc_;     ///< per element, the L_c bend_ratio_ was evaluated at
    BendingKernel bending_kernel_ = BendingKernel::Dkt;
    // Smoothed membrane (control.membrane: smoothed)
    bool smoothed_membrane_ = false;
    std::vector<Index> side_neighbour_, side_neighbour_side_;  ///< per element side (3 e + i), -1: none
    std::vector<int> side_neighbour_corner_;  ///< per side, the neighbour's corners of its ends (i+1, i+2)
    std::vector<ReversedTriangle> reversed_;  ///< per element, this step's path element
    std::vector<Voigt3> cst_strain_;          ///< per element, this step's CST strain increment
    std::vector<std::size_t> point_offset_;    ///< first material point of every element (plastic, computed alone)
    std::vector<MaterialPoint> points_;        ///< material points of those elements
    std::size_t n_plastic_points_ = 0;         ///< points of all plastic elements
    std::vector<std::size_t> stress_offset_;   ///< first stress of every element (elastic, computed alone)
    std::vector<Voigt3> elastic_stress_;       ///< stresses of the points of those elements
    std::size_t n_elastic_points_ = 0;         ///< points of all elastic elements
    // Element-corner slots: the force and moment on each corner of every element (and, with
    // the smoothed membrane, on the node across each side), kept like the block state: groups
    // of k_lanes slots, component by component (fx fy fz mx my mz, k_lanes values each), so that
    // a block stores its corner loads as 6 whole packs per corner. Slot sigma lies in group
    // sigma / k_lanes at lane sigma % k_lanes; corner i of block b is slot (3 b + i) k_lanes +
    // lane, and the elements computed alone follow the blocks, slots_per_alone_ slots each.
    // Only the slots that are used exist: 3 per element without the smoothed membrane.
    std::vector<Real, Eigen::aligned_allocator<Real>> slot_loads_;
    std::vector<Index> alone_position_;  ///< per element: its index in scalar_elements_, -1: in a block
    std::size_t slots_per_alone_ = 3;
    /// Offset in slot_loads_ of component 0 of slot k of element e (component c: + c k_lanes).
    [[nodiscard]] std::size_t slot_offset(std::size_t e, std::size_t k) const;
    std::vector<Index> csr_begin_;  ///< particle -> its slots (csr_slot_[csr_begin_[p]...])
    std::vector<std::size_t> csr_slot_;  ///< slot_offset of each slot, by particle, in element order
    /// When each particle is summed, and from where (ring or slot_loads_); made for a thread
    /// count, remade when it changes.
    SlotGatherPlan gather_plan_;
    /// The ranges of blocks the element loop runs: one per thread (1 for a model small enough
    /// to stay serial).
    [[nodiscard]] int gather_ranges() const;
    // SIMD blocks (elements/elastic_triangle_block.hpp)
    std::vector<ElasticSectionConstants> elastic_constants_;  ///< per section (zero if not elastic)
    std::vector<Index> block_elements_;   ///< k_lanes elements of one section per block
    std::vector<Index> block_lane_;       ///< per element: its index in block_elements_, -1: computed alone
    /// The block and the lane of index `at` of block_elements_ (at >= 0).
    [[nodiscard]] static std::pair<std::size_t, int> block_and_lane(Index at) {
        const auto i = static_cast<std::size_t>(at), w = static_cast<std::size_t>(k_lanes);
        return {i / w, static_cast<int>(i % w)};
    }
    std::vector<std::size_t> block_state_offset_;  ///< per block: its first pack in block_state_
    /// the point states of the blocks, [block][field][point] (point_fields), one lane per element
    std::vector<RealPack> block_state_;
    std::vector<Index> scalar_elements_;  ///< the elements computed one by one
    std::vector<ElementTotals> block_totals_;  ///< per block
    std::vector<ElementTotals> alone_totals_;  ///< per element computed alone (scalar_elements_ order)
    std::vector<ElementTotals> chunk_totals_;  ///< scratch, per chunk of blocks and elements alone
    /// N and M of the elements of the blocks, 6 packs per block (N then M, component by
    /// component); those of the elements computed alone in membrane_force_, bending_moment_.
    std::vector<RealPack> block_resultants_;
    /// Component c of N (c < 3) or of M (c - 3) of element e, wherever it is kept.
    [[nodiscard]] Voigt3 resultant(std::size_t e, std::size_t first) const;
    void set_resultants(std::size_t e, const Voigt3& n, const Voigt3& m);
    std::vector<Voigt3> membrane_force_, bending_moment_;  ///< per element computed alone (others: zero)
    Real stiffness_damping_ = 0;
};

}  // namespace fpmshell
