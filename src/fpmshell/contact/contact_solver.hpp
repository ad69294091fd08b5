// Contact of the shell with itself and with rigid bodies (theory.md §8): detection by a bucket
// grid rebuilt at a cadence set by the fastest particle, gaps between the thickness-offset
// surfaces, and two ways to enforce them:
//  - Lagrange multipliers, forward increment (default; Carpenter, Taylor & Katona 1991): the
//    contact forces at t_n are those that make the predicted positions x^{n+1} satisfy every
//    gap, found by projected Gauss-Seidel sweeps (§8.3). They do not reduce the stable step and
//    make each impact perfectly plastic in the normal direction.
//  - Penalty (fallback): a force proportional to the penetration at t_n, stiffness = scale x
//    pair mass / dt^2 (like LS-DYNA's SOFT = 1), elastic.
// The solver owns the contact forces it computes; the caller adds them to the particles.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "fpmshell/contact/bucket_grid.hpp"
#include "fpmshell/contact/constraint_islands.hpp"
#include "fpmshell/contact/multiplier_memory.hpp"
#include "fpmshell/contact/rigid_body_state.hpp"
#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

class RestartWriter;
class RestartReader;

struct ContactStatistics {
    long active = 0;      ///< contact forces (constraints with a force) of the last step
    long max_active = 0;  ///< most at any step
    int sweeps = 0;       ///< Gauss-Seidel sweeps of the last step
    int max_sweeps = 0;
    long unconverged_steps = 0;  ///< steps that ended at max_iterations
    long searches = 0;           ///< broad-phase rebuilds
    /// Constraints that started a step already inside by more than 1e-3 of their offset and
    /// were held there (Lagrange multipliers); 0 in a clean run.
    long held_penetrations = 0;
    /// Largest penetration of a thickness-offset surface left at the end of any step, and
    /// the same divided by the thickness of the slave particle.
    Real max_penetration = 0;
    Real max_penetration_ratio = 0;
    long max_penetration_step = -1;
    Index max_penetration_particle = -1;
    Index max_penetration_element = -1;  ///< -1 when it was against a rigid body
    double seconds = 0;                  ///< wall time spent in contact (search + enforcement)
    /// Self-contact particles that start closer to a face than their thickness offsets (initial
    /// penetrations, counted at the first search; left out of the contact with those faces by
    /// the exclusion radius, theory.md R8)
    long initial_penetrations = 0;
    /// Self-contact pairs dropped by their clearance (theory.md eq. 8.1d) without being
    /// computed, over the run
    long pairs_skipped = 0;
};

class ContactSolver {
public:
    /// inv_mass: per particle and direction, 0 where the motion is fixed or prescribed.
    /// element_thickness: per element of the model.
    /// topology: the model's, for the 2-ring of every slave (§8.1).
    ContactSolver(const Model& model, const MeshTopology& topology,
                  const std::vector<Vec3>& inv_mass, const std::vector<Real>& element_thickness);

    /// The inverse mass of particle p (per direction, as in the constructor) after its mass
    /// changed (mass scaling during the run, §6.10).
    /// Per particle its rigid body, -1 outside them (after spot welds failed, eq. 6.11-13).
    void set_rigid_body_of(const std::vector<Index>& body_of_particle) {
        rigid_body_of_ = body_of_particle;
    }
    void set_inverse_mass(Index p, const Vec3& inv_mass) {
        inv_mass_[static_cast<std::size_t>(p)] = inv_mass;
    }

    [[nodiscard]] bool empty() const { return definitions_.empty(); }
    [[nodiscard]] bool has_penalty() const { return has_penalty_; }
    [[nodiscard]] bool has_lagrange() const { return has_lagrange_; }
    /// Every particle the contact reads (the slaves of every definition and the nodes of the
    /// self-contact triangles), ascending: what a distributed run shares before the contact.
    [[nodiscard]] std::vector<Index> particles() const;

    /// Penalty definitions: forces at t_n from the positions x^n, added to f_contact and to
    /// the bodies' force, with their friction against the velocities v^{n-1/2} (eq. 8.4-6).
    /// beta_* = c1 dt_n dt_{n+1/2} (the position change per unit force times the mass) of the
    /// particles and of the bodies. motion: the largest particle displacement since the last
    /// call (sets the search cadence).
    void penalty_forces(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                        const std::vector<Vec3>& body_u, std::vector<RigidBodyState>& bodies,
                        Real beta_particle, Real beta_body, Real dt_new, Real motion, long step,
                        std::vector<Vec3>& f_contact);

    /// Lagrange-multiplier definitions: corrects the predicted positions x_pred (particles)
    /// and body_u_pred (bodies) so that no gap is negative at t_{n+1}, and adds the forces
    /// that do it (acting at t_n) to f_contact and to the bodies' force. x: positions x^n;
    /// dt_new: dt_{n+1/2}, over which x_pred was predicted (the sliding speed of eq. 8.4-5).
    void enforce(const std::vector<Vec3>& x, std::vector<Vec3>& x_pred,
                 std::vector<Vec3>& body_u_pred, std::vector<RigidBodyState>& bodies,
                 Real beta_particle, Real beta_body, Real dt_new, Real motion, long step,
                 std::vector<Vec3>& f_contact);

    [[nodiscard]] const ContactStatistics& statistics() const { return stats_; }
    /// After a particle separation (theory.md §7.7): this contact of the separated mesh goes on
    /// with the statistics of `before` (the contact of the mesh before it), and counts no
    /// initial penetrations (its crack faces start together and leave each other out).
    void continue_from(const ContactSolver& before) {
        stats_ = before.stats_;
        initial_counted_ = true;
    }
    /// The contact force at t_n on the slaves of definition k: for a self-contact the push on
    /// the particles of its pairs' slave side (LS-DYNA's RCFORC slave side), for a rigid contact
    /// the force on its particles (minus the body's share of it).
    [[nodiscard]] const Vec3& slave_force(std::size_t k) const { return slave_force_[k]; }

    /// What collect_self takes of a triangle once per step: its unit normals at x^n and at the
    /// predictor y, and a sphere about its face at y.
    struct TriangleFrame {
        Vec3 n_x = Vec3::Zero(), n_y = Vec3::Zero(), centre_y = Vec3::Zero();
        Real radius_y = 0;
    };

    /// The candidate pairs (slave particle, triangle) of definition `definition` found by its
    /// last search (none before the first).
    [[nodiscard]] std::vector<std::pair<Index, Index>> candidate_pairs(
        std::size_t definition) const;

    /// The smallest numbers of slaves (search, collection) and of constraints (sweeps) run in
    /// parallel; smaller ones run on one thread. The results are the same either way: tests
    /// lower them to run a small model's contact in parallel (constraints 0: the sweeps in
    /// parallel whatever the islands' sizes).
    void set_parallel_minimum(std::size_t slaves, std::size_t constraints) {
        parallel_min_slaves_ = slaves;
        parallel_min_constraints_ = constraints;
    }

    /// Whether collect_self drops pairs by their clearance (theory.md eq. 8.1d; on by default).
    /// The constraints are the same either way: tests switch it off to compare.
    void set_pair_clearances(bool on) { pair_clearances_ = on; }

    /// The state carried from step to step (search cadence, candidates, statistics), for a
    /// restart file (io/restart_archive.hpp).
    /// Theory.md §7.6: the faces of the eroded elements `eroded` leave the self-contacts
    /// (their particles stay as slaves). With search_again the next step searches anew (the
    /// candidates found before may hold those faces); a resumed run's loaded candidates were
    /// found after the erosion, and stay.
    void drop_faces(const std::vector<Index>& eroded, bool search_again);
    void save(RestartWriter& out) const;
    void load(RestartReader& in);

private:
    /// One gap constraint: slave particle s against the point sum xi_k x_k of triangle
    /// `element` (or the face of rigid body `body`), along the unit normal n (frozen at the
    /// predictor, theory.md §8.2): g = n.(x_s - sum xi_k x_k) - offset.
    struct Constraint {
        Index slave = -1;
        Index element = -1;  ///< -1 for a rigid body
        Index body = -1;
        std::array<Index, 3> master{-1, -1, -1};
        std::array<Real, 3> xi{};
        Vec3 normal = Vec3::Zero();
        Vec3 anchor = Vec3::Zero();  ///< rigid body: its face point below the slave at t = 0
        Real offset = 0;
        Real gap = 0;     ///< at the positions it was built on
        Real weight = 0;  ///< W = sum beta (n.M^-1 n) of its particles and body
        Real lambda = 0;
        Real thickness = 1;            ///< slave thickness, for penetration ratios
        Real allowance = 0;            ///< penetration it already had at t_n (held, not pushed out)
        Real friction = 0;             ///< Coulomb coefficient (Lagrange; infinity: no sliding)
        std::uint32_t definition = 0;  ///< index of its contact definition
        /// the sweeps' bookkeeping: the gap at its last evaluation and the update count then
        Real last_gap = 0;
        std::int64_t evaluated_at = -1;
    };

    struct Definition {
        ContactDefinition def;
        std::vector<Index> slaves;                  ///< self: nodes of the elements
        std::vector<Real> slave_offset;             ///< h_s / 2 per slave
        std::vector<std::int64_t> neighbour_start;  ///< CSR per slave: its edge neighbours
        std::vector<Index> neighbours;
        Real max_offset = 0;  ///< largest (h_s + h_e) / 2
        Real exclusion_radius = 0;
        Real margin = 0;     ///< extra search distance
        Real travelled = 0;  ///< relative motion bound since the last search
        bool searched = false;
        std::vector<std::int64_t> candidate_start;  ///< CSR per slave
        std::vector<Index> candidates;              ///< triangles
        /// per candidate: collect_self drops the pair without computing it while travelled plus
        /// the activation distance stays below this (eq. 8.1d); -inf: not known to be clear
        std::vector<Real> candidate_clear;
        /// the triangles among the candidates, once each (collect_self's frames; empty after
        /// a search until collect_self remakes it)
        std::vector<Index> candidate_triangles;
    };

    void search(Definition& d, const std::vector<Vec3>& x);
    /// Self-contact constraints of definition d: geometry at x (side of each pair, §8.2) and
    /// gaps at y (the predictor for Lagrange multipliers, x itself for the penalty).
    void collect_self(Definition& d, const std::vector<Vec3>& x, const std::vector<Vec3>& y,
                      bool lagrange, std::vector<Constraint>& out, std::vector<Constraint>& closed);
    /// Rigid-face constraints at positions y; lagrange: also the particles near the face.
    void collect_rigid(const Definition& d, const std::vector<Vec3>& y,
                       const std::vector<Vec3>& body_u, bool lagrange,
                       std::vector<Constraint>& out);
    [[nodiscard]] Real weight(const Constraint& c, Real beta_particle, Real beta_body,
                              const std::vector<RigidBodyState>& bodies) const {
        return weight_along(c, c.normal, beta_particle, beta_body, bodies);
    }
    /// The position change per unit force of constraint c along the unit direction `along`
    /// (eqs. 8.3-2, 8.4-2): the slave, the face's corners by their xi^2, the body.
    [[nodiscard]] Real weight_along(const Constraint& c, const Vec3& along, Real beta_particle,
                                    Real beta_body,
                                    const std::vector<RigidBodyState>& bodies) const;
    void note_penetration(Real penetration, const Constraint& c, long step);
    /// The predicted positions after constraint c's multiplier grows by dl (§8.3): its particles
    /// and body move by beta dl M^-1 G; with stamp >= 0 the sweeps' bookkeeping records that
    /// they moved at that update.
    void move_by(const Constraint& c, Real dl, std::vector<Vec3>& x_pred,
                 std::vector<Vec3>& body_u_pred, const std::vector<RigidBodyState>& bodies,
                 Real beta_particle, Real beta_body, std::int64_t stamp);
    /// The slip of constraint c's slave against its body or face point over the step (x^n to
    /// x_pred), in the tangent plane (eq. 8.4-1).
    [[nodiscard]] Vec3 tangential_slip(const Constraint& c, const std::vector<Vec3>& x,
                                       const std::vector<Vec3>& x_pred,
                                       const std::vector<Vec3>& body_u_pred,
                                       const std::vector<RigidBodyState>& bodies) const;
    /// §8.4: the tangential multiplier `lambda_t` of constraint c (at x: the positions x^n)
    /// moves to the one that stops the slave's slip against the body or face over the step,
    /// within the Coulomb cone |lambda_t| <= mu lambda; returns its change.
    /// The friction force on the slave of a penalty constraint (eq. 8.4-6): Coulomb's
    /// mu lambda against its sliding velocity, at most what stops the sliding in the step.
    [[nodiscard]] Vec3 penalty_friction(const Constraint& c, const std::vector<Vec3>& v,
                                        const std::vector<RigidBodyState>& bodies,
                                        Real beta_particle, Real beta_body, Real dt_new) const;
    Vec3 slide(const Constraint& c, Vec3& lambda_t, const std::vector<Vec3>& x,
               std::vector<Vec3>& x_pred, std::vector<Vec3>& body_u_pred,
               const std::vector<RigidBodyState>& bodies, Real beta_particle, Real beta_body,
               std::int64_t stamp);
    /// The identity of constraint c from step to step (§8.3a).
    [[nodiscard]] static MultiplierMemory::Key key_of(const Constraint& c);
    /// §8.3a: the constraints start from the multipliers the memory kept for their keys, and
    /// the predicted positions move by what those multipliers do.
    void warm_start(std::vector<Vec3>& x_pred, std::vector<Vec3>& body_u_pred,
                    const std::vector<RigidBodyState>& bodies, Real beta_particle, Real beta_body);
    /// Keeps the positive multipliers of this step's constraints for the next (§8.3a).
    void keep_multipliers();
    void prepare_search(Definition& d, const std::vector<Vec3>& x, Real motion);
    [[nodiscard]] std::uint32_t definition_index(const Definition& d) const {
        return static_cast<std::uint32_t>(&d - definitions_.data());
    }
    template <class Archive>
    void transfer_state(Archive& ar);

    const Model& model_;
    std::vector<Vec3> inv_mass_;
    /// Sweep bookkeeping (enforce): per particle and rigid body, the count of its island's
    /// updates in this step at which its predicted position last changed (-1: not yet).
    std::vector<std::int64_t> particle_moved_at_, body_moved_at_;
    /// The largest values of one sweep over an island, for the convergence test (§8.3).
    struct SweepMeasures {
        Real deepest = 0, largest_change = 0, largest_lambda = 0, largest_move = 0;
    };
    MultiplierMemory memory_;  ///< the last step's multipliers (§8.3a)
    std::vector<std::pair<MultiplierMemory::Key, Real>> memory_entries_;  ///< scratch
    ConstraintIslands islands_;
    std::vector<ConstraintIslands::Nodes> island_nodes_;  ///< scratch, per constraint
    std::vector<Real> penetration_;  ///< scratch, per constraint: left at t_{n+1}
    /// per constraint: its tangential (friction) multiplier, a force in the tangent plane
    /// (§8.4); sized only in steps with friction
    std::vector<Vec3> friction_lambda_;
    std::vector<int> island_sweeps_;  ///< scratch, per island: its sweeps, < 0 unconverged
    std::vector<std::int64_t> island_updates_;  ///< scratch, per island
    std::vector<Real> element_thickness_;
    std::vector<Real> node_thickness_;
    /// per particle, its rigid body (model/rigid_body_partition.hpp), -1 outside them: a body's
    /// particles never touch its own faces
    std::vector<Index> rigid_body_of_;
    std::vector<Index> mesh_piece_;  ///< per particle: its piece of the mesh (R8's exclusion)
    std::vector<Definition> definitions_;
    std::vector<Vec3> slave_force_;  ///< per definition: the force on its slaves at t_n
    bool has_penalty_ = false, has_lagrange_ = false;
    BucketGrid grid_;
    std::vector<Vec3> box_lo_, box_hi_;             ///< scratch for the grid
    std::vector<Constraint> constraints_, closed_;  ///< scratch, reused every step
    std::vector<TriangleFrame> frames_;             ///< scratch of collect_self, per triangle
    Real motion_ = 0;  ///< enforce: the largest predictor motion of the step (activation)
    /// What one chunk of slaves finds (collect_self runs the chunks in parallel): the unkeyed
    /// constraints, those already through at t_n, and the edge and corner constraints with their
    /// keys; `unique` lists the latter in key order, the first found of equal keys only.
    struct SortKey {  ///< a key as two integers and the constraint's place in the chunk
        std::uint64_t high = 0;
        std::uint32_t low = 0, index = 0;
    };
    struct CollectBuffers {
        std::vector<Constraint> out, closed, keyed;
        std::vector<std::array<Index, 3>> keys;
        std::vector<SortKey> sorted;  ///< scratch
        std::vector<std::size_t> unique;
        std::size_t out_at = 0, closed_at = 0;  ///< where the chunk's lists go in the output
    };
    /// scratch of the merge of the chunks' keyed constraints: the next key of each chunk, and
    /// the merged list (key, chunk, index in the chunk's `keyed`)
    struct MergeHead {
        std::size_t chunk = 0, next = 0;
    };
    struct MergedKey {
        std::array<Index, 3> key{};
        std::size_t chunk = 0, index = 0;
    };
    std::vector<MergeHead> merge_heads_;
    std::vector<MergedKey> merged_;
    static constexpr std::size_t k_collect_chunk = 256;  ///< slaves per chunk
    std::vector<CollectBuffers> collect_chunks_;         ///< scratch, per chunk
    std::vector<std::vector<Index>> search_chunks_;      ///< scratch: candidates per chunk
    ContactStatistics stats_;
    bool initial_counted_ = false;  ///< the initial penetrations counted (continue_from)
    /// Below, a parallel region costs more than it shares out: 2 000 slaves like the particle
    /// passes (solver/explicit_solver.cpp); 512 constraints, since a parallel sweep costs a
    /// barrier per sweep, more than a few hundred constraint updates.
    std::size_t parallel_min_slaves_ = 2000;
    std::size_t parallel_min_constraints_ = 512;
    bool pair_clearances_ = true;
};

}  // namespace fpmshell
