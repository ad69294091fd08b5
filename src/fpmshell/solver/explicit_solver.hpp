// The explicit FPM solver (theory.md §6.8): the cycle t_n -> t_{n+1} as a list of phases —
// element loop, normals and external loads, stable step, contact, central difference for
// translations and tangent-plane rotations, boundary conditions, energy balance — for dynamic
// runs and for dynamic relaxation (control.mode: relaxation, §6.9), which runs the same cycle.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "fpmshell/contact/contact_solver.hpp"
#include "fpmshell/contact/rigid_body_state.hpp"
#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/model/particle_separation.hpp"
#include "fpmshell/solver/boundary_conditions.hpp"
#include "fpmshell/solver/cycle_policy.hpp"
#include "fpmshell/solver/domain_decomposition.hpp"
#include "fpmshell/solver/edge_opening.hpp"
#include "fpmshell/solver/energy_balance.hpp"
#include "fpmshell/solver/external_loads.hpp"
#include "fpmshell/solver/mass_scaling.hpp"
#include "fpmshell/solver/nodal_rigid_bodies.hpp"
#include "fpmshell/solver/particle_state.hpp"
#include "fpmshell/solver/rank_exchange.hpp"
#include "fpmshell/solver/shell_elements.hpp"
#include "fpmshell/solver/tied_surfaces.hpp"

namespace fpmshell {

class RestartWriter;
class RestartReader;

class ExplicitSolver {
public:
    /// Sets up masses (§6.1), rotary inertia (§6.2 option B), kink particles (§1.3), boundary
    /// masks and initial velocities. The model must outlive the solver.
    explicit ExplicitSolver(const Model& model);
    /// §7.7 the solver of `separated` (model/separated_model.hpp: `before`'s model separated by
    /// `separation`) taking over `before`'s state after its step: each new particle its
    /// parent's motion and its group's share of the parent's mass and rotary inertia, every
    /// element its state. Collective on a distributed run (the ranks are cut anew).
    ExplicitSolver(const Model& separated, ExplicitSolver& before, const Separation& separation);
    ~ExplicitSolver();
    ExplicitSolver(const ExplicitSolver&) = delete;
    ExplicitSolver& operator=(const ExplicitSolver&) = delete;

    /// One dynamic cycle t_n -> t_{n+1}; the step is the stable one, limited to max_dt.
    /// Throws RunFailure (with step, particle or element) when the state becomes invalid.
    void step(Real max_dt);

    struct RelaxResult {
        bool converged = false;
        long iterations = 0;
        Real residual_ratio = 0;  ///< |out-of-balance| / |external + reactions|
    };
    /// Dynamic relaxation (§6.9) to static equilibrium under the loads at load parameter load_time
    /// (kinetic damping: velocities are zeroed at every peak of the kinetic energy).
    RelaxResult relax(Real load_time);

    /// Stable step for the current geometry: time_step_scale * min element step (§6.4).
    [[nodiscard]] Real stable_dt() const;

    [[nodiscard]] Real time() const { return time_; }
    [[nodiscard]] long steps() const { return steps_; }
    [[nodiscard]] long element_steps() const { return element_steps_; }
    [[nodiscard]] Real last_dt() const { return dt_half_; }
    /// control.minimum_time_step's floor on the step (0: none).
    [[nodiscard]] Real minimum_step() const { return min_step_; }
    [[nodiscard]] const ParticleState& state() const { return s_; }
    [[nodiscard]] const ShellElements& elements() const { return elements_; }
    [[nodiscard]] const EnergyBalance& energy() const { return energy_; }
    /// Elements eroded so far (theory.md §7.6), and the time of the first erosion (-1: none).
    [[nodiscard]] Index eroded_elements() const { return eroded_elements_; }
    [[nodiscard]] Real first_erosion_time() const { return first_erosion_time_; }
    /// §7.7 the particle separation that the edges opened so far call for after the last step
    /// (nullptr: none): the run then goes on with the solver of the separated model.
    [[nodiscard]] const Separation* separation_due() const {
        return separation_due_ ? &*separation_due_ : nullptr;
    }
    /// §7.7 the sides opened so far, and the particles the separations have added.
    [[nodiscard]] std::size_t open_sides() const { return opening_.open().size(); }
    [[nodiscard]] const std::vector<ElementPair>& open_side_pairs() const {
        return opening_.open();
    }
    [[nodiscard]] Index split_particles() const { return split_particles_; }
    /// §7.7 the sides opened and the separations so far (in restart files: a resumed run's
    /// model is the one read, replay_separations of it).
    [[nodiscard]] const SeparationHistory& separation_history() const { return history_; }
    /// The rigid bodies (§6.11), and through them the spot welds that failed (eq. 6.11-13).
    [[nodiscard]] const NodalRigidBodies& nodal_rigid_bodies() const { return nodal_rigid_bodies_; }
    /// The sheets' plastic strain at the ductile welds' particles, at the last step (eq. 6.11-15).
    [[nodiscard]] const WeldSheetStrain& weld_sheet_strain() const { return weld_sheet_strain_; }
    [[nodiscard]] const Model& model() const { return model_; }
    [[nodiscard]] const MeshTopology& topology() const { return topology_; }
    /// The mass added by control.mass_scaling per section (§6.10; zero without it).
    [[nodiscard]] const AddedMass& added_mass() const { return added_mass_; }
    /// a^n = (v^{n+1/2} - v^{n-1/2}) / dt_n of the last cycle.
    [[nodiscard]] Vec3 acceleration(Index p) const;
    /// Rigid bodies (model order): displacement at t_{n+1}, velocity v^{n+1/2}, contact force at
    /// t_n.
    [[nodiscard]] const std::vector<RigidBodyState>& bodies() const { return bodies_; }
    /// a^n of rigid body b.
    [[nodiscard]] Vec3 body_acceleration(Index b) const;
    /// Contact statistics (nullptr without contact).
    /// The contact force at t_n on the slaves of contact definition k (0 without contact).
    [[nodiscard]] Vec3 contact_force(Index k) const {
        return contact_ ? contact_->slave_force(static_cast<std::size_t>(k)) : Vec3::Zero();
    }
    /// The ties of `constraints` of type tied (§6.12), nullptr without them.
    [[nodiscard]] const TiedSurfaces* tied_surfaces() const { return tied_.get(); }
    [[nodiscard]] const ContactStatistics* contact_statistics() const {
        return contact_ ? &contact_->statistics() : nullptr;
    }

    /// The ranks of a distributed run (core/communicator.hpp) and this one's share.
    [[nodiscard]] const DomainDecomposition& decomposition() const {
        return ranks_.decomposition();
    }
    /// The whole state of a dynamic run at t_n, for a restart file (io/restart_archive.hpp):
    /// a solver built from the same model and loaded continues bitwise like this one. With
    /// `in_pieces` (a distributed run) without the particles' and elements' state, which every
    /// rank writes of its own with save_piece.
    void save(RestartWriter& out, bool in_pieces = false) const;
    /// This rank's piece of a distributed run's restart file: the state of the particles it
    /// owns and of the elements it computes, after its step and time.
    void save_piece(RestartWriter& out) const;
    /// The reader of the piece that rank r wrote (RestartFiles opens the files).
    using RestartPieces = std::function<RestartReader(int rank)>;
    /// Loads a restart file: whole (`pieces` 0), or written on `pieces` ranks, whose pieces
    /// `open_piece` opens; they may have been written on any number of ranks. Throws
    /// InputError when the file or a piece belongs to another model (other particles or
    /// elements), to another step, or is damaged.
    void load(RestartReader& in, int pieces = 0, const RestartPieces& open_piece = {});

private:
    /// The lengths of this cycle's steps and the central-difference factors (§6.6):
    /// dt_n = (dt_{n-1/2} + dt_{n+1/2}) / 2, c1 = 1 / (1 + a_m dt_n / 2), c2 = 1 - a_m dt_n / 2.
    struct StepLengths {
        Real dt_n = 0, dt_new = 0, c1 = 1, c2 = 1, a_m = 0;
        /// the run's first cycle: x^{-1} is taken as x^0 - dt_n v^{-1/2} in the works (§6.8)
        bool first = false;
        /// the weight of the last step's forces in this step's works: 1, but 1/2 in the second
        /// cycle, whose velocity update of t_0 spanned dt_n = dt_{1/2} / 2 (eq. 6.8-3)
        Real prev_weight = 1;
    };
    /// Sums over the particles of one cycle: kinetic energy, work of loads and reactions,
    /// contact work, damping, the count of non-finite states (energies at t_n, §6.8), then the
    /// out-of-balance and applied loads squared (relaxation residual).
    struct ParticleSums {
        Real kinetic = 0, external_work = 0, contact_work = 0, damping = 0, non_finite = 0;
        Real rounding = 0;  ///< of this step's works (eq. 6.8-2)
        Real residual2 = 0, reference2 = 0;
        Real damping_ahead = 0;  ///< eq. 6.8-4
    };
    /// The state of the cycle, with `particles` the particles' too.
    template <class Archive>
    void transfer_state(Archive& ar, bool particles);
    /// The particles' and elements' state from the pieces of a distributed restart file
    /// (`in`: its restart.bin, for the messages): each must hold them once.
    void load_pieces(const RestartReader& in, int ranks, const RestartPieces& pieces);

    /// The cycle t_n -> t_{n+1} (§6.8), shared by dynamic and relaxation modes. load_time: the
    /// time at which loads and prescribed motions are evaluated; dt_cap: the largest step.
    void cycle(const CyclePolicy& policy, Real load_time, Real dt_cap);
    // The phases of the cycle, in its order.
    /// 1 element loop on the path element (x^{n-1}, x^n, dtheta^{n-1/2}) -> f_int^n, m_int^n
    /// (§2-§5); books the strain, plastic and damping work.
    [[nodiscard]] ShellElements::StepTotals compute_internal_loads(const CyclePolicy& policy);
    /// 1 (§6.10) the mass and inertia the element loop added to the elements whose step fell
    /// below the target of control.mass_scaling, given to their particles.
    void add_scaled_mass();
    /// §7.6: the faces of the elements eroded this step leave the self-contacts.
    void drop_eroded_faces();
    /// The contact's inverse masses of the nodal rigid bodies' particles: their bodies'
    /// (eq. 6.11-5), after the masses changed.
    void refresh_contact_masses();
    /// §7.7 (eq. 7.7-1): the failed elements open their sides, judged on this step's membrane
    /// forces at x^n (every rank learns every rank's); then whether a separation is due.
    void open_failed_sides();
    /// §7.7 the state of `before` (the same mesh up to the separation) taken over.
    void take_state(ExplicitSolver& before, const Separation& separation);
    /// After spot welds failed (eq. 6.11-13): the contact's masses and rigid bodies anew.
    void release_failed_welds();
    /// 3 dt_{n+1/2} = scale min dt_e, growth capped at 1.2 dt_{n-1/2} (§6.4), and dt_n.
    [[nodiscard]] StepLengths next_step_lengths(const CyclePolicy& policy,
                                                const ShellElements::StepTotals& elements,
                                                Real dt_cap);
    /// 4 contact forces at t_n: the penalty forces from x^n (the multipliers come after the
    /// velocity update).
    void penalty_contact(const StepLengths& dt);
    /// 5 central difference (§6.6) with the fixed components removed and their reactions, fused
    /// with 8-9 (energies at t_n and x^{n+1}) in one sweep over the particle arrays: taken when
    /// nothing changes v^{n+1/2} in between (no prescribed motion, no Lagrange contact).
    [[nodiscard]] ParticleSums update_velocities_and_advance_particles(const CyclePolicy& policy,
                                                                       const StepLengths& dt);
    /// 5 central difference alone (the sweep above without 8-9).
    [[nodiscard]] ParticleSums update_velocities(const CyclePolicy& policy, const StepLengths& dt);
    /// 6 prescribed motions (§6.7) and the rigid bodies' velocities.
    [[nodiscard]] PrescribedMotionTimes prescribed_motion_times(const CyclePolicy& policy,
                                                                Real load_time,
                                                                const StepLengths& dt) const;
    void impose_prescribed_motions(const CyclePolicy& policy, Real load_time,
                                   const StepLengths& dt);
    void update_body_velocities(const StepLengths& dt);
    /// 7 Lagrange-multiplier contact (§8.3): corrects v^{n+1/2} so that x^{n+1} satisfies every
    /// gap.
    void lagrange_contact(const StepLengths& dt);
    /// 8-9 energies at t_n (into sums) and x^{n+1}, dtheta^{n+1/2} of every particle (the
    /// second sweep).
    void advance_particles(const StepLengths& dt, ParticleSums& sums);
    /// Kinetic damping's measure of the motion at v^{n+1/2} (twice the kinetic energy), summed
    /// atom by atom: the same bits on any number of threads and ranks.
    [[nodiscard]] Real kinetic_measure();
    /// 8 the energy balance at t_n (§6.8) from the particles' sums and the rigid bodies.
    void book_energies(const StepLengths& dt, const ParticleSums& particles);
    /// 9 the rigid bodies' positions, the step lengths and the step count.
    void finish_step(const StepLengths& dt, const ParticleSums& particles);

    // Per particle (inlined in the sweeps above).
    /// v^{n+1/2}, w^{n+1/2} and the reactions of particle p; with policy.residual, its
    /// out-of-balance and applied loads squared added to residual[0], residual[1].
    void update_particle_velocity(std::size_t p, const CyclePolicy& policy, const StepLengths& dt,
                                  Real* residual);
    /// The energies of particle p at t_n added to energy[0..3] (kinetic, work of loads and
    /// reactions, contact work, damping), energy[4] += 1 if its new state is not finite,
    /// energy[5] the rounding of its works (eq. 6.8-2); then its x^{n+1} and rotation increment.
    void advance_particle(std::size_t p, const StepLengths& dt, Real* energy);

    /// Whether particle p at `position` has a finite state: the position, its angular velocity
    /// and internal force (defined here so that the per-step particle pass inlines it; that
    /// pass checks the new position before it becomes s_.x).
    [[nodiscard]] bool finite_state(std::size_t p, const Vec3& position) const {
        return position.allFinite() && s_.omega[p].allFinite() && s_.f_int[p].allFinite();
    }
    /// Sums of a sweep over the particles (particle_update.cpp): body(p, sums) on every held
    /// particle, the sums of the owned ones added atom by atom, exactly, over the ranks.
    template <int N, class Body>
    std::array<Real, N> atom_sums(std::vector<std::array<Real, N>>& scratch, Body&& body);
    /// The largest of value(p) over the particles (over the ranks: each over those it owns).
    template <class F>
    [[nodiscard]] Real max_over_particles(F&& value) const;
    /// Throws RunFailure naming the first particle whose state is not finite.
    void report_non_finite_state() const;
    /// Throws RunFailure naming the failed element.
    [[noreturn]] void report_failed_element(Index e) const;
    /// Throws RunFailure when the energy balance error exceeds control.energy_error_limit.
    void check_energy_balance() const;
    /// Kinetic damping: moves the state back to the kinetic-energy peak bracketed by the last
    /// three half steps (Barnes 1988).
    void move_to_kinetic_energy_peak(Real ke_before, Real ke_peak, Real ke_after);

    const Model& model_;
    MeshTopology topology_;
    ShellElements elements_;
    RankExchange ranks_;  ///< this rank's share and the traffic between the ranks
    AddedMass added_mass_;
    ParticleState s_;
    EnergyBalance energy_;
    std::unique_ptr<BoundaryConditions> bc_;  ///< built once the kink particles are known
    std::unique_ptr<ExternalLoads> loads_;
    std::vector<RigidBodyState> bodies_;
    std::unique_ptr<ContactSolver> contact_;  ///< null without contact definitions
    NodalRigidBodies nodal_rigid_bodies_;     ///< `constraints` and rigid materials (§6.11)
    WeldSheetStrain weld_sheet_strain_;       ///< at the ductile welds (eq. 6.11-15)
    std::unique_ptr<TiedSurfaces> tied_;      ///< `constraints` of type tied (§6.12)
    /// per particle, the mass the contact gives it (its body's, eq. 6.11-5); empty without
    /// contact or nodal rigid bodies
    std::vector<Real> contact_mass_;
    /// §7.7: the sides opened, the particles that never split, the separation due
    EdgeOpening opening_;
    std::vector<std::uint8_t> pinned_;
    std::optional<Separation> separation_due_;
    SeparationHistory history_;
    Index split_particles_ = 0;
    /// Steps 5 and 8-9 in one sweep (update_velocities_and_advance_particles).
    bool fused_particle_pass_ = false;
    bool parallel_particles_ = false;  ///< particle loops in parallel (large models)
    Real length_scale_ = 1;  ///< mean edge length: converts moments to forces in residuals
    std::vector<Vec3> x_pred_, body_u_pred_;           ///< contact scratch: predicted x^{n+1}
    std::vector<Vec3> x_pred_before_, body_u_before_;  ///< the predictor before the multipliers
    std::vector<std::array<Real, 1>> sums1_;           ///< scratch: per-chunk partial sums
    std::vector<std::array<Real, 2>> sums2_;
    std::vector<std::array<Real, 7>> sums7_;
    std::vector<std::array<Real, 9>> sums9_;
    Real time_ = 0;
    Real dt_half_ = 0;       ///< dt_{n-1/2} (0 before the first step)
    Real dt_half_prev_ = 0;  ///< the step before dt_half_
    Real dt_center_ = 0;     ///< dt_n of the last cycle
    long steps_ = 0;
    Index eroded_elements_ = 0;     ///< §7.6, over the run
    Real first_erosion_time_ = -1;  ///< §7.6, -1 until an element erodes
    bool restart_ = false;          ///< next cycle restarts from rest (kinetic damping)
    long element_steps_ = 0;
    Real residual2_ = 0, reference2_ = 0;  ///< relaxation residual of the last cycle
    Index min_dt_element_ = -1;            ///< the element of the last step's smallest step
    Real min_step_ = 0;  ///< control.minimum_time_step's floor on the step (0: none)
};

}  // namespace fpmshell
