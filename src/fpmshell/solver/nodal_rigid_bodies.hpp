// Nodal rigid bodies (model-format.md `constraints`, theory.md §6.11): groups of particles that
// move as one rigid body, as LS-DYNA's *CONSTRAINED_NODAL_RIGID_BODY and its spot welds do, and
// the sections of a rigid material (LS-DYNA's *MAT_RIGID parts). Each
// step, after the particles' free velocity update, the velocities of a body's particles are
// replaced by the rigid motion of the same linear and angular momentum, with the rotation
// applied exactly so that the body keeps its shape to rounding.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/model/rigid_body_partition.hpp"
#include "fpmshell/model/spot_weld_sides.hpp"
#include "fpmshell/solver/boundary_conditions.hpp"
#include "fpmshell/solver/weld_sheet_strain.hpp"

namespace fpmshell {

struct ParticleState;

class NodalRigidBodies {
public:
    /// The model's groups (`constraints` of type rigid, and the particles of each section of a
    /// rigid material), those that share a particle merged into one body (two rigid bodies
    /// joined at a particle are one: model/rigid_body_partition.hpp). A `boundary` entry of type
    /// rigid_body that cannot be applied is an InputError.
    explicit NodalRigidBodies(const Model& model);

    [[nodiscard]] bool empty() const { return bodies_.empty(); }
    /// The bodies after merging, each a sorted list of particles.
    [[nodiscard]] const std::vector<std::vector<Index>>& bodies() const { return bodies_; }
    /// Per body, its velocity components held (x, y, z, then rotations about them): at zero
    /// by the rigid materials merged into it and by `fix` of a `boundary` entry of type
    /// rigid_body (eq. 6.11-6), or at the values such an entry prescribes (eq. 6.11-7).
    [[nodiscard]] const std::vector<std::array<bool, 6>>& fixed() const { return fixed_; }
    /// The particles of the bodies with a prescribed motion, ascending: their velocity changes
    /// in make_rigid are reactions that do work (the energy balance books them, §6.8).
    [[nodiscard]] std::vector<Index> driven_particles() const;

    /// The initial velocities of every body's particles made one rigid motion of the same
    /// linear and angular momentum (eqs. 6.11-1 to 6.11-3 with v = V + w x r): a deck that gives
    /// a body's nodes uneven velocities starts, and books its kinetic energy, as that motion.
    void make_initial_motion_rigid(ParticleState& s) const;
    /// The particles of the rigid sections with a given inertia: they turn about all three axes
    /// (their rotary inertia is part of the body's, eq. 6.11-10).
    [[nodiscard]] std::vector<Index> full_rotation_particles() const;
    /// The kinetic energy of the bodies' inertia that their particles do not carry (eq.
    /// 6.11-10): 1/2 w^{n-1/2} . dJ(t_n) w^{n+1/2} summed over the bodies with a given inertia.
    [[nodiscard]] Real extra_kinetic_energy(const ParticleState& s) const;

    /// The mass the contact gives each particle (eq. 6.11-5): that of its body, or its own
    /// (`mass`) outside the bodies.
    [[nodiscard]] std::vector<Real> contact_masses(const std::vector<Real>& mass) const;

    /// Eqs. 6.11-1 to 6.11-4 (6.11-6 for a body with fixed components, 6.11-7 with prescribed
    /// ones): the half-step velocities v^{n+1/2} and the tangent-plane angular velocities of
    /// every body's particles become one rigid motion with their linear and angular momentum
    /// about the centre of mass at x^n, such that x^{n+1} = x^n + dt v is that rigid motion
    /// exactly. A driven body's particles add the change of their velocities to their reactions.
    /// The bodies run in parallel (each writes its own particles).
    /// `again`: the second pass of a step, after the contact changed the velocities the first
    /// pass made rigid.
    /// The constraint impulses m (v_rigid - v_free) of the spot welds' sides are summed over
    /// the passes of the step for judge_welds.
    void make_rigid(ParticleState& s, const PrescribedMotionTimes& at,
                    const std::vector<Curve>& curves, bool again = false);

    /// Eq. 6.11-13, after the step's last make_rigid: each spot weld that can fail and has not
    /// judges the force it carried, its side's impulses over `impulse_time` (c1 dt_n), against
    /// its limits, `time` (t_{n+1}) against its failure time, and the plastic strain of the
    /// sheets at its particles (`sheets`, eq. 6.11-15) against its own. The welds that fail
    /// let go for good: the bodies are formed again without them. Returns how many failed now.
    std::size_t judge_welds(const ParticleState& s, Real impulse_time, Real time,
                            const WeldSheetStrain& sheets);
    /// The spot welds that have failed, and the time the first did (-1 before).
    [[nodiscard]] std::size_t failed_welds() const;
    [[nodiscard]] Real first_weld_failure_time() const { return first_weld_failure_time_; }
    /// Whether some spot weld can fail (the model has failure data on a weld).
    [[nodiscard]] bool has_failing_welds() const { return !let_go_.empty(); }
    /// Per entry of Model::nodal_rigid_bodies (empty where no weld can fail): whether it has
    /// failed, and at the last judge_welds the force it carried onto its first particle's side
    /// (a generalized weld: onto the side of its particle nearest failure, eq. 6.11-14), its
    /// tension and its shear (zero for a failed weld or a group that cannot fail).
    [[nodiscard]] const std::vector<std::uint8_t>& welds_failed() const { return let_go_; }
    [[nodiscard]] const std::vector<Vec3>& weld_forces() const { return weld_force_; }
    [[nodiscard]] const std::vector<Real>& weld_tensions() const { return weld_tension_; }
    [[nodiscard]] const std::vector<Real>& weld_shears() const { return weld_shear_; }
    /// Per entry, for a generalized weld that can fail (more than two particles; eq. 6.11-14):
    /// at the last judge_welds the force through it onto each of its particles' sides, in the
    /// group's order (empty for other entries; zero once it has failed).
    [[nodiscard]] const std::vector<std::vector<Vec3>>& generalized_weld_forces() const {
        return node_force_;
    }
    /// Per particle its body, -1 outside the bodies.
    [[nodiscard]] const std::vector<Index>& body_of_particle() const { return body_of_particle_; }

    /// The failed welds, for a restart file (io/restart_archive.hpp); call rebuild after loading.
    template <class Archive>
    void transfer(Archive& ar) {
        ar(let_go_);
        ar(first_weld_failure_time_);
    }
    /// Whether a loaded state fits these welds.
    [[nodiscard]] bool restored() const {
        return let_go_.empty() || let_go_.size() == model_->nodal_rigid_bodies.size();
    }
    /// The bodies formed again from the model without the failed welds.
    void rebuild();

private:
    /// The velocity (k < 3) or angular velocity (k >= 3) component k of body b at this step,
    /// its centre of mass at x^n `centre` and at t = 0 `centre0`, its velocity V^{n-1/2}
    /// `velocity_prev`.
    [[nodiscard]] Real prescribed_value(std::size_t b, std::size_t k, const Vec3& centre,
                                        const Vec3& centre0, const Vec3& velocity_prev,
                                        const PrescribedMotionTimes& at,
                                        const std::vector<Curve>& curves) const;

    /// A body with sections of a given inertia (eq. 6.11-10): the part dJ of its inertia
    /// tensor that its particles' masses and rotary inertias leave out, at t = 0, and three of
    /// its particles that give its rotation R(t) (eq. 6.11-11); dJ(t) = R dJ0 R^T.
    struct InertiaCorrection {
        std::size_t body = 0;
        Mat3 delta0 = Mat3::Zero();
        Index o = -1, a = -1, b = -1;  ///< o also carries the body's angular velocity
        Mat3 frame0_inverse = Mat3::Identity();
    };
    void set_inertia_corrections(const Model& model, const std::vector<Index>& body_of_particle);
    /// R(t) of correction c from its particles' positions (eq. 6.11-11).
    [[nodiscard]] static Mat3 rotation_of(const InertiaCorrection& c, const std::vector<Vec3>& x);

    /// The welds' side particles and their slots in weld_impulse_ (eq. 6.11-13).
    void set_weld_sides();
    /// What a weld carries at the step's end (eqs. 6.11-13, 6.11-14): the force onto the side it
    /// is judged on, its tension and shear, and the criterion's value (failed at 1).
    struct WeldLoad {
        Vec3 force = Vec3::Zero();
        Real tension = 0, shear = 0, criterion = 0;
    };
    /// The force through the weld onto `side`: its particles' constraint impulses over the time.
    [[nodiscard]] Vec3 side_force(const std::vector<Index>& side, Real impulse_time) const;
    /// force split along the unit `axis` (tension positive; either way for coincident ends).
    [[nodiscard]] static WeldLoad load_along(const NodalRigidBody& group, const Vec3& force,
                                             const Vec3& axis, bool coincident);
    [[nodiscard]] WeldLoad weld_load(const SpotWeldSide& w, const ParticleState& s,
                                     Real impulse_time) const;
    WeldLoad generalized_weld_load(const SpotWeldSide& w, const ParticleState& s,
                                   Real impulse_time);

    const Model* model_ = nullptr;
    std::vector<std::vector<Index>> bodies_;
    std::vector<Index> body_of_particle_;
    std::vector<InertiaCorrection> corrections_;  ///< ascending in body
    std::vector<Index> full_rotation_;
    std::vector<std::array<bool, 6>> fixed_;
    std::vector<std::array<RigidPrescription, 6>> prescribed_;  ///< per body; empty: none anywhere
    std::vector<std::uint8_t> driven_;                          ///< per body: some value prescribed
    /// per entry of Model::nodal_rigid_bodies, 1 once its weld failed; empty: no weld can fail
    std::vector<std::uint8_t> let_go_;
    Real first_weld_failure_time_ = -1;
    std::vector<SpotWeldSide> welds_;  ///< the welds that can still fail
    std::vector<Index> weld_slot_;     ///< per particle: its slot, -1 on no weld side
    std::vector<Vec3> weld_impulse_;   ///< per slot: the step's constraint impulse
    std::vector<Vec3> weld_force_;     ///< per entry, at the last judge_welds
    /// per entry, for a generalized weld: the force onto each of its particles' sides
    std::vector<std::vector<Vec3>> node_force_;
    std::vector<Real> weld_tension_, weld_shear_;
};

}  // namespace fpmshell
