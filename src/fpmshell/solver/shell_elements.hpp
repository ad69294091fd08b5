// The element loop: the element groups of the model (one per section: its material, rule and
// material points, solver/element_group.hpp), and the assembly of their corner loads into
// particles (solver/corner_assembly.hpp).
#pragma once

#include <array>
#include <limits>
#include <memory>
#include <vector>

#include "fpmshell/core/communicator.hpp"
#include "fpmshell/core/types.hpp"
#include "fpmshell/elements/shell_triangle.hpp"
#include "fpmshell/failure/element_erosion.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/corner_assembly.hpp"
#include "fpmshell/solver/domain_decomposition.hpp"
#include "fpmshell/solver/element_group.hpp"
#include "fpmshell/solver/element_time_steps.hpp"
#include "fpmshell/solver/particle_state.hpp"
#include "fpmshell/solver/range_balancer.hpp"

namespace fpmshell {

class RestartWriter;
class RestartReader;

/// The units of work of the element loop of `model` (its SIMD blocks and the elements computed
/// alone, corner_assembly.hpp), as ShellElements forms them, without allocating their state.
[[nodiscard]] ElementBlocks element_units(
    const Model& model, const ElementGroupFactory& make_group = make_element_group);

class ShellElements {
public:
    /// topology: the model's (side neighbours, element masses); it must outlive this.
    /// make_group: the group of each section (make_element_group: the model's materials).
    /// state_now: the state of every element's points and its corner slots made now; without
    /// it set_decomposition makes those of the elements this rank computes (a distributed
    /// run's memory).
    ShellElements(const Model& model, const MeshTopology& topology,
                  const ElementGroupFactory& make_group = make_element_group,
                  bool state_now = true);

    struct StepTotals {
        Real strain_work = 0;   ///< sum of element strain work over the step
        Real damping_work = 0;  ///< sum of viscous work over the step
        Real plastic_work = 0;  ///< sum of plastic dissipation over the step (in strain_work)
        Real min_dt = 0;        ///< smallest element critical step at t_n (§6.4), unscaled
        Index min_dt_element = -1;
        Index failed_element = -1;  ///< first degenerate or flipped element, -1 if none
        /// elements whose step fell below the target of §6.10 mass scaling this step (their
        /// factors wait in time_steps().take_pending_scaling())
        Index mass_scaled = 0;
        Index eroded_elements = 0;  ///< elements eroded this step (§7.6)
        Real eroded_work = 0;       ///< their strain work over the run, this step's included
    };

    /// Internal forces and moments at t_n from the path element (x_prev, x, dtheta); writes
    /// s.f_int, s.m_int and updates the material points. viscous_rate = a_s / dt_{n-1/2};
    /// dt = dt_{n-1/2} for rate-dependent materials (0 in relaxation: no rate effects).
    StepTotals compute(ParticleState& s, Real viscous_rate, Real dt);
    /// t_n of the next compute, for the failure criteria of a time (FailurePacks::time).
    void set_time(Real t) { time_ = t; }

    /// Critical step of every element from the current geometry (§6.4), unscaled, minimum.
    [[nodiscard]] Real min_critical_dt(const std::vector<Vec3>& x, Index* where = nullptr) const;
    /// Critical step of element e at positions x (§6.4), unscaled.
    [[nodiscard]] Real critical_dt(Index e, const std::vector<Vec3>& x) const {
        return time_steps_.critical_dt(
            e, current_length(e, x),
            ElementTimeSteps::volume_factor(time_steps_.initial_volume(static_cast<std::size_t>(e)),
                                            current_volume(e, x)));
    }

    /// The elements' critical steps (§6.4), for the set-up's mass scaling (§6.10).
    [[nodiscard]] ElementTimeSteps& time_steps() { return time_steps_; }
    [[nodiscard]] const ElementTimeSteps& time_steps() const { return time_steps_; }

    [[nodiscard]] Index size() const { return static_cast<Index>(tri_.size()); }
    /// The units, slots and particle -> slot map of the element loop.
    [[nodiscard]] const CornerAssembly& assembly() const { return assembly_; }
    /// Membrane force N and bending moment M of element e averaged over the element, in its
    /// local frame, at the end of the last step.
    [[nodiscard]] Voigt3 membrane_force(Index e) const {
        return resultant(static_cast<std::size_t>(e), 0);
    }
    [[nodiscard]] Voigt3 bending_moment(Index e) const {
        return resultant(static_cast<std::size_t>(e), 3);
    }
    /// Equivalent plastic strain of element e averaged over its in-plane points, at the
    /// thickness point of index k (0 = bottom, n-1 = top).
    [[nodiscard]] Real plastic_strain(Index e, int k) const;
    /// Equivalent plastic strain of element e averaged over all its points by the rule's
    /// weights (in the plane and through the thickness): its mean over the element's volume.
    [[nodiscard]] Real mean_plastic_strain(Index e) const;
    /// The state of point p of element e (the points of its section's rule, in-plane major).
    [[nodiscard]] MaterialPoint point_state(Index e, std::size_t p) const {
        const auto ue = static_cast<std::size_t>(e);
        return group_of(ue).point_state(place_of(ue), p);
    }
    [[nodiscard]] int thickness_points(Index e) const {
        return static_cast<int>(group_of(static_cast<std::size_t>(e)).rule().through.size());
    }
    /// Whether some section's material can fail (theory.md §7.6), and whether element e has
    /// eroded: it no longer acts (no loads, no time step), its particles keep their mass.
    [[nodiscard]] bool can_erode() const { return !eroded_.empty(); }
    /// control.minimum_time_step with erode: an element whose critical step (unscaled, §6.4)
    /// falls below dt erodes (§7.6), whatever its material (0: none).
    void set_erosion_step(Real dt) { erosion_step_ = dt; }
    [[nodiscard]] bool eroded(Index e) const {
        return !eroded_.empty() && eroded_[static_cast<std::size_t>(e)] != 0;
    }
    /// The elements eroded in the last step (of those this rank computes), and all eroded
    /// so far, in element order.
    [[nodiscard]] std::vector<Index> eroded_in_last_step() const;
    [[nodiscard]] std::vector<Index> eroded_so_far() const;
    /// Eq. 6.4-3 after erosion: the elements `eroded` (this step's, of every rank, sorted)
    /// leave their side neighbours; those left in a piece of one or two elements joined by
    /// their sides take their exact membrane step from now on (their ratios at the corners x).
    void steady_small_pieces(const std::vector<Index>& eroded, const std::vector<Vec3>& x);
    /// The same flags from all the elements eroded so far (of every rank) without re-evaluating
    /// a ratio: a restart's or a separation's element state brings them.
    void mark_small_pieces(const std::vector<Index>& eroded);
    /// §7.7 whether some section's material separates (`fracture: separate`): its failed
    /// elements keep acting and open an edge each.
    [[nodiscard]] bool separates() const { return !cracked_.empty(); }
    /// §7.7 the failed elements that have not opened their edge (of those this rank computes),
    /// in element order; whether element e has failed; e has opened its edge (every rank).
    [[nodiscard]] std::vector<Index> failed_unopened() const;
    [[nodiscard]] bool cracked(Index e) const {
        return !cracked_.empty() && cracked_[static_cast<std::size_t>(e)] != 0;
    }
    void mark_opened(Index e) { cracked_[static_cast<std::size_t>(e)] = k_opened; }
    /// Current thickness of element e (the section's, or updated by §3.4).
    [[nodiscard]] Real thickness(Index e) const { return thickness_[static_cast<std::size_t>(e)]; }

    /// The state carried from step to step (material points, thickness, bending step ratios,
    /// resultants), for a restart file (io/restart_archive.hpp).
    void save(RestartWriter& out) const;
    void load(RestartReader& in);

    /// A distributed run: compute only the units of `d` (null: all), receive the other ranks'
    /// slots at the shared particles, sum only the held particles; keep the state of those
    /// units alone where it was not made at construction. d must outlive this.
    void set_decomposition(const DomainDecomposition* d);
    /// Whether this rank computes element e (every element on one rank).
    [[nodiscard]] bool computes(Index e) const;
    /// The numbers this rank keeps of the state of the points and of the failure criteria
    /// (its memory's largest per-element part on plastic models).
    [[nodiscard]] std::size_t kept_state_numbers() const;
    /// The elements this rank computes (its units of the element loop, blocks then those
    /// alone; every element on one rank).
    [[nodiscard]] std::vector<Index> computed_elements() const;
    /// The state of the elements this rank computes, as bytes for unpack_state (a
    /// distributed run's pieces of a restart file).
    [[nodiscard]] std::vector<char> pack_state() const;
    /// Counts each element in `seen` (one entry per element). Throws
    /// std::invalid_argument for states cut short or of an element this model lacks (states
    /// read from a file).
    void unpack_state(const std::vector<char>& bytes, std::vector<std::uint8_t>& seen);

private:
    /// What the step totals need of a set of elements (a block, an element computed alone,
    /// a chunk of them): its works, its smallest critical step and the lowest-numbered element
    /// with it, the lowest-numbered failed element (-1: none).
    struct ElementTotals {
        Real strain_work = 0, damping_work = 0, plastic_work = 0;
        Real dt = std::numeric_limits<Real>::infinity();
        Index dt_element = -1, failed = -1;
        Index mass_scaled = 0;             ///< elements given added mass this step (§6.10)
        Index eroded = 0;                  ///< elements eroded this step (§7.6)
        Real eroded_work = 0;              ///< their strain work over the run
        void add(const ElementTotals& o);  ///< o's works added after this one's
    };
    /// The smoothed membrane's view of an element's neighbours (membrane_smoothing.hpp).
    struct SmoothedStrain {
        Voigt3 strain = Voigt3::Zero();     ///< the smoothed membrane strain increment
        Real own_share = 1;                 ///< the element's own share of its membrane loads
        std::array<Mat3, 3> to_here;        ///< neighbour strain -> this frame, per side
        std::array<Real, 3> side_weight{};  ///< weight of the neighbour's strain, per side
    };

    /// The group of element e, and where its state lies there.
    [[nodiscard]] const ElementGroup& group_of(std::size_t e) const {
        return *groups_[static_cast<std::size_t>(section_[e])];
    }
    [[nodiscard]] GroupPlace place_of(std::size_t e) const;
    /// L_c = 2A / l_max of element e at positions x (§6.4).
    [[nodiscard]] Real current_length(Index e, const std::vector<Vec3>& x) const;
    /// A h of element e at positions x, h its current thickness (eq. 6.4-2).
    [[nodiscard]] Real current_volume(Index e, const std::vector<Vec3>& x) const;
    /// Path element of element e (§2).
    [[nodiscard]] ReversedTriangle reverse_element(std::size_t e, const ParticleState& s) const;
    /// Smoothed membrane, first pass: every element's path element and CST strain increment.
    void reverse_all_elements(const ParticleState& s, bool parallel);
    /// The smoothed membrane strain of element e from its neighbours' CST strains.
    [[nodiscard]] SmoothedStrain smoothed_strain(std::size_t e,
                                                 const LocalTriangle<Real>& rt) const;
    /// Adds the neighbours' share of element e's membrane forces to its slots across the sides.
    void add_neighbour_loads(std::size_t e, const LocalTriangle<Real>& rt, const SmoothedStrain& sm,
                             const Voigt3& n);
    /// §7.6: the erosion rule of each section, and the per-element state where one can fail.
    void init_erosion(const Model& model);
    /// The state of the points and of the failure criteria (§7.6) of the units this rank
    /// computes (all without a decomposition), at its initial values.
    void allocate_state();
    void allocate_failure_state();
    /// Where the arrays per block (totals, resultants, initial volumes, element sizes) keep
    /// block b: the blocks this rank computes, in order.
    [[nodiscard]] std::size_t kept_block(std::size_t b) const {
        return block_store_.empty() ? b : block_store_[b];
    }
    /// Whether this rank computes unit u (blocks, then the elements computed alone).
    [[nodiscard]] bool computes_unit(std::size_t u) const {
        return !decomposition_ || !decomposition_->distributed() || decomposition_->own_unit[u];
    }
    /// §7.6 after element e's step (of duration dt) of strain work `work`: adds the work to
    /// the element's, brings its failure criteria up to the step, and erodes it where its
    /// section's rule says so (booked in t), keeping its corner loads (per corner: force x y z,
    /// moment x y z) for book_last_half_step. Only where some material can fail (erosion_ not
    /// empty).
    /// verdict: whether the element erodes, where its block's criteria have judged it
    /// (judge_block); nullptr: judged here.
    void check_erosion(std::size_t e, Real work, Real dt, ElementTotals& t,
                       const std::array<Real, 18>& corner_loads, const bool* verdict = nullptr);
    /// §7.6 the failure criteria of the k_lanes elements of block b after the step: which erode
    /// (false where their section cannot fail). Returns false where the section's law has them
    /// judged element by element.
    bool judge_block(Index b, Real dt, std::array<bool, k_lanes>& erodes);
    /// eq. 7.6-6 the fading of block b's points (into `out`; nullptr where its section does
    /// not fade), read and written in place.
    [[nodiscard]] const StressFading<RealPack>* block_fading(Index b, StressFading<RealPack>& out);
    /// The same of element e computed alone: its points' numbers copied into `f`, which
    /// keep_element_fading writes back after the element's step.
    struct ElementFading {
        std::array<Real, k_max_block_points> next, applied;  // filled where view is set
        StressFading<Real> view{};
    };
    [[nodiscard]] const StressFading<Real>* element_fading(std::size_t e, ElementFading& f);
    void keep_element_fading(std::size_t e, const ElementFading& f);
    /// §7.6 whether element e erodes, its criteria judged on its own points.
    bool erodes_alone(std::size_t e, Real dt);
    /// §7.6 the criteria's state number i (of failure_numbers(e), [number][point]) of element
    /// e, and how many it has (0 where none is kept).
    [[nodiscard]] Real& failure_number(std::size_t e, std::size_t i);
    [[nodiscard]] std::size_t failure_numbers(std::size_t e) const {
        if (!keeps_failure_state_) return 0;
        const ElementErosion& rule = erosion_[static_cast<std::size_t>(section_[e])];
        return rule.fields() * rule.n_points();
    }
    /// §7.6 the step after element e eroded: the work of its last loads over the half step
    /// they acted in, into t's strain and eroded work.
    void book_last_half_step(std::size_t e, const ParticleState& s, ElementTotals& t);
    static constexpr std::uint8_t k_eroded = 1, k_eroded_pending = 2;  ///< eroded_ values
    static constexpr std::uint8_t k_failed = 1, k_opened = 2;          ///< cracked_ values
    /// One element by the general (scalar) code; its totals: see ElementTotals.
    [[nodiscard]] ElementTotals compute_element(Index e, ParticleState& s, Real viscous_rate,
                                                Real dt);
    /// The k_lanes elements of block b (lanes outside the block kernel's bounds go to
    /// compute_element). Its corner loads go to ring_slots (the block's place in a ring of
    /// slot_gather_plan.hpp; nullptr: none) and, where the plan keeps the block or there is
    /// no ring, to the full slot array.
    void compute_block(Index b, ParticleState& s, Real viscous_rate, Real dt, Real* ring_slots);
    /// The slots of the shared particles to and from the other ranks: sent (from the blocks
    /// computed first) while the interior blocks compute, received after them.
    [[nodiscard]] Communicator::Pending start_slot_exchange();
    void finish_slot_exchange(Communicator::Pending& pending);
    /// The step's totals from the units' (and, distributed, over the ranks).
    [[nodiscard]] StepTotals step_totals();
    /// The ranges of blocks the element loop runs: one per thread (1 for a model small enough
    /// to stay serial).
    [[nodiscard]] int gather_ranges() const;
    /// Component c of N (c < 3) or of M (c - 3) of element e, wherever it is kept.
    [[nodiscard]] Voigt3 resultant(std::size_t e, std::size_t first) const;
    void set_resultants(std::size_t e, const Voigt3& n, const Voigt3& m);

    std::vector<std::array<Index, 3>> tri_;
    std::vector<Index> section_;  ///< per element: its section, and group
    const MeshTopology* topology_;
    /// per element: eroded on some rank (steady_small_pieces' view; eroded_ holds this rank's)
    std::vector<std::uint8_t> gone_;
    Real erosion_step_ = 0;  ///< set_erosion_step's
    /// per section: its material's `failure: {minimum_time_step}` as an unscaled critical step
    /// (over time_step_scale, as erosion_step_), 0: none
    std::vector<Real> material_erosion_step_;
    [[nodiscard]] bool gone(Index e) const { return gone_[static_cast<std::size_t>(e)] != 0; }
    std::vector<std::unique_ptr<ElementGroup>> groups_;  ///< per section
    ElementTimeSteps time_steps_;
    CornerAssembly assembly_;
    RangeBalancer balancer_;       ///< the threads' ranges of blocks by measured time
    std::vector<Real> thickness_;  ///< per element, current h
    /// §7.6, all empty where no material can fail: per section its erosion rule; per element
    /// 0 live, k_eroded_pending the step after it eroded, then k_eroded; its strain work so
    /// far (of the sections that can fail), and the loads of the step it eroded in
    std::vector<ElementErosion> erosion_;
    std::vector<std::uint8_t> eroded_;
    std::vector<Real> element_work_;
    std::vector<std::array<Real, 18>> last_loads_;  ///< corner loads of the eroding step
    /// §7.7, empty where no material separates: per element 0 intact, k_failed once failed
    /// (on the rank that computes it), k_opened once it has opened its edge (on every rank)
    std::vector<std::uint8_t> cracked_;
    /// the failure criteria's state (failure/element_erosion.hpp): a block's from the pack
    /// failure_state_at_[e] of its elements on, an element computed alone's from its own;
    /// empty where no criterion keeps any
    std::vector<RealPack> failure_state_;
    bool keeps_failure_state_ = false;           ///< some criterion keeps a state per point
    bool state_made_ = false;                    ///< allocate_state has run
    Real time_ = 0;                              ///< t_n of the step computed (set_time)
    std::vector<std::size_t> failure_state_at_;  ///< per element
    std::vector<Real> element_size_;  ///< per element, sqrt(2 A_0) (where some material can fail)
    std::vector<RealPack> block_element_size_;  ///< the same per block kept, a lane per element
    bool thickness_update_ = false;
    bool smoothed_membrane_ = false;          ///< control.membrane: smoothed
    std::vector<ReversedTriangle> reversed_;  ///< smoothed: per element, this step's path element
    std::vector<Voigt3> cst_strain_;  ///< smoothed: per element, this step's CST strain increment
    /// per block: where its arrays below keep it (empty: every block, in order; KeptPlaces)
    std::vector<std::size_t> block_store_;
    std::vector<ElementTotals> block_totals_;  ///< per block kept (kept_block)
    std::vector<ElementTotals>
        alone_totals_;  ///< per element computed alone (alone_elements order)
    /// N and M of the elements of the blocks, 6 packs per block (N then M, component by
    /// component); those of the elements computed alone in membrane_force_, bending_moment_.
    std::vector<RealPack> block_resultants_;
    std::vector<RealPack>
        block_initial_volume_;  ///< per block kept, A_0 h_0 of its lanes (eq. 6.4-2)
    std::vector<Voigt3> membrane_force_,
        bending_moment_;  ///< per element computed alone (ElementBlocks::alone_elements order)
    const DomainDecomposition* decomposition_ = nullptr;
    std::vector<std::uint8_t> not_in_ring_loop_;  ///< distributed: per block, skipped there
    std::vector<std::vector<Real>> slot_send_, slot_recv_;  ///< exchange_slots buffers
};

}  // namespace fpmshell
