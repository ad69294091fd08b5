// The explicit FPM cycle (theory.md §6.8): element loop -> external loads -> variable-step
// central difference for translations and tangent-plane rotations -> boundary conditions ->
// energy balance. Also dynamic relaxation (control.mode: relaxation) built on the same cycle.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "fpmshell/contact/contact_solver.hpp"
#include "fpmshell/contact/rigid_body_state.hpp"
#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/energy_balance.hpp"
#include "fpmshell/solver/particle_state.hpp"
#include "fpmshell/solver/shell_elements.hpp"

namespace fpmshell {

class RestartWriter;
class RestartReader;

class ExplicitSolver {
public:
    /// Sets up masses (§6.1), rotary inertia (§6.2 option B), kink particles (§1.3), boundary
    /// masks and initial velocities. The model must outlive the solver.
    explicit ExplicitSolver(const Model& model);

    /// One dynamic cycle t_n -> t_{n+1}; the step is the stable one, limited to max_dt.
    /// Throws RunFailure (with step, particle or element) when the state becomes invalid.
    void step(Real max_dt);

    struct RelaxResult {
        bool converged = false;
        long iterations = 0;
        Real residual_ratio = 0;  ///< |out-of-balance| / |external + reactions|
    };
    /// Dynamic relaxation to static equilibrium under the loads at load parameter load_time
    /// (kinetic damping: velocities are zeroed at every peak of the kinetic energy).
    RelaxResult relax(Real load_time);

    /// Stable step for the current geometry: time_step_scale * min element step (§6.4).
    [[nodiscard]] Real stable_dt() const;

    [[nodiscard]] Real time() const { return time_; }
    [[nodiscard]] long steps() const { return steps_; }
    [[nodiscard]] long element_steps() const { return element_steps_; }
    [[nodiscard]] Real last_dt() const { return dt_half_; }
    [[nodiscard]] const ParticleState& state() const { return s_; }
    [[nodiscard]] const ShellElements& elements() const { return elements_; }
    [[nodiscard]] const EnergyBalance& energy() const { return energy_; }
    [[nodiscard]] const Model& model() const { return model_; }
    /// a^n = (v^{n+1/2} - v^{n-1/2}) / dt_n of the last cycle.
    [[nodiscard]] Vec3 acceleration(Index p) const;
    /// Rigid bodies (model order): displacement at t_{n+1}, velocity v^{n+1/2}, contact force at t_n.
    [[nodiscard]] const std::vector<RigidBodyState>& bodies() const { return bodies_; }
    /// a^n of rigid body b.
    [[nodiscard]] Vec3 body_acceleration(Index b) const;
    /// Contact statistics (nullptr without contact).
    [[nodiscard]] const ContactStatistics* contact_statistics() const {
        return contact_ ? &contact_->statistics() : nullptr;
    }

    /// The whole state of a dynamic run at t_n, for a restart file (io/restart_archive.hpp):
    /// a solver built from the same model and loaded continues bitwise like this one.
    void save(RestartWriter& out) const;
    /// Throws InputError when the file belongs to another model (other particles).
    void load(RestartReader& in);

private:
    template <class Archive>
    void transfer_state(Archive& ar);
    struct Prescribed {
        Index particle;
        PrescribedKind kind;
        Vec3 value;
        Index curve;
    };

    /// The cycle shared by dynamic and relaxation modes. load_time: time at which loads and
    /// prescribed motions are evaluated; advance: whether time moves on (dynamic) or not.
    void cycle(Real load_time, Real dt_new_cap, bool relaxation);
    /// The tangent-plane normals of the current positions (§1.3) and the external loads at
    /// time t (§6.7), whose pressures use the triangles' current cross products.
    void update_normals_and_loads(Real t);
    [[nodiscard]] Real curve_value(Index curve, Real t) const;
    [[nodiscard]] Real curve_integral(Index curve, Real t) const;
    /// Whether particle p at `position` has a finite state: the position, its angular velocity
    /// and internal force (defined here so that the per-step particle pass inlines it; that
    /// pass checks the new position before it becomes s_.x).
    [[nodiscard]] bool finite_state(std::size_t p, const Vec3& position) const {
        return position.allFinite() && s_.omega[p].allFinite() && s_.f_int[p].allFinite();
    }
    /// The drill axis of particle p for the tangent-plane normal n (§2.6, eq. 2.6c): the axis
    /// about which its rotation increment is neither integrated nor constrained.
    [[nodiscard]] Vec3 drill_axis(std::size_t p, const Vec3& n) const {
        switch (drill_kind_[p]) {
            case DrillKind::Normal:
                return n;
            case DrillKind::InSymmetryPlane: {  // the normal in the plane normal to the free axis
                const Vec3 a = Vec3::Unit(drill_free_axis_[p]);
                const Vec3 v = n - n.dot(a) * a;
                const Real len = v.norm();
                return len > 1e-8 ? Vec3(v / len) : Vec3::Zero();
            }
            case DrillKind::None:
                break;
        }
        return Vec3::Zero();
    }
    /// Throws RunFailure naming the first particle whose state is not finite.
    void report_non_finite_state() const;
    /// Penalty contact forces at t_n (before the velocity update).
    void penalty_contact(Real dt_n, Real dt_new, Real c1);
    /// Lagrange-multiplier contact: corrects v^{n+1/2} so that x^{n+1} satisfies every gap.
    void lagrange_contact(Real dt_n, Real dt_new, Real c1);
    /// Kinetic damping: moves the state back to the kinetic-energy peak bracketed by the last
    /// three half steps (Barnes 1988).
    void move_to_kinetic_energy_peak(Real ke_before, Real ke_peak, Real ke_after);

    const Model& model_;
    MeshTopology topology_;
    ShellElements elements_;
    ParticleState s_;
    EnergyBalance energy_;
    std::vector<std::array<bool, 6>> fixed_;  ///< per particle, ux uy uz rx ry rz
    std::vector<std::uint8_t> prescribed_translation_, prescribed_rotation_;
    /// What a particle's rotation increment lacks (§2.6, eq. 2.6c): nothing (a kink, a prescribed
    /// rotation, a clamp), the rotation about its normal (tangent-plane rotations), or, on a
    /// symmetry plane that leaves one rotation free, the rotation about its normal turned
    /// into that plane.
    enum class DrillKind : std::uint8_t { None, Normal, InSymmetryPlane };
    std::vector<DrillKind> drill_kind_;
    std::vector<Eigen::Index> drill_free_axis_;  ///< InSymmetryPlane: the free rotation component
    /// per particle: a fixed or prescribed component (the only ones with reactions; a free
    /// particle's stay zero and are neither written nor read by the time loop)
    std::vector<std::uint8_t> constrained_;
    bool has_moment_loads_ = false;  ///< m_ext can be nonzero (else neither written nor read)
    std::vector<Prescribed> prescribed_;
    std::vector<Vec3> prescribed_rotation_applied_;  ///< relaxation: rotation imposed so far
    std::vector<RigidBodyState> bodies_;
    std::unique_ptr<ContactSolver> contact_;     ///< null without contact definitions
    std::vector<Vec3> inv_mass_;                 ///< per particle and direction; 0 where fixed or prescribed
    std::vector<Vec3> x_pred_, body_u_pred_;     ///< contact scratch: predicted x^{n+1}
    std::vector<Vec3> x_pred_before_, body_u_before_;  ///< the predictor before the multipliers
    Real time_ = 0;
    Real dt_half_ = 0;       ///< dt_{n-1/2} (0 before the first step)
    Real dt_half_prev_ = 0;  ///< the step before dt_half_
    Real dt_center_ = 0;     ///< dt_n of the last cycle
    long steps_ = 0;
    bool restart_ = false;   ///< next cycle restarts from rest (kinetic damping)
    long element_steps_ = 0;
    Real length_scale_ = 1;  ///< mean edge length: converts moments to forces in residuals
    bool parallel_particles_ = false;  ///< particle loops in parallel (large models)
    std::vector<Index> node_element_begin_, node_element_;  ///< CSR particle -> triangles
    std::vector<Vec3> element_cross_;                       ///< scratch: (x2 - x1) x (x3 - x1)
    struct PressureGather {  ///< per pressure load: loaded particle -> its loaded triangles (CSR)
        std::vector<Index> particle, begin, element;
    };
    std::vector<PressureGather> pressure_gather_;  ///< per load (empty unless a pressure)
    bool fused_pressure_ = false;  ///< load 0: a pressure on every triangle, summed with the normals
    std::vector<std::array<Real, 2>> sums2_;                ///< scratch: per-chunk partial sums
    std::vector<std::array<Real, 5>> sums5_;
    std::vector<std::array<Real, 7>> sums7_;
    // Relaxation residual of the last cycle.
    Real residual2_ = 0, reference2_ = 0;
};

}  // namespace fpmshell
