// The constraints of the particles (theory.md §6.7): fixed degrees of freedom, symmetry planes,
// prescribed displacements, velocities and angular velocities, and what each constraint leaves
// of a particle's rotation — its tangent plane (§1.3), the one free axis of a symmetry plane,
// or nothing — with the drill axis that follows from it (§2.6, eq. 2.6c). Built once from the
// Model; the particle update asks it per particle.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/particle_state.hpp"

namespace fpmshell {

/// The times and step lengths at which prescribed motions are imposed in one cycle.
struct PrescribedMotionTimes {
    Real load_time = 0;  ///< t_n (dynamic) or the load parameter (relaxation)
    Real t_half = 0;     ///< t_{n+1/2}: prescribed velocities
    Real t_next = 0;     ///< t_{n+1}: prescribed displacements
    Real dt_n = 0, dt_new = 0, c1 = 1;
    bool relaxation = false;  ///< velocities and rotations reach the integral of the curve
};

class BoundaryConditions {
public:
    /// full_rotation: the kink particles (§1.3), whose three rotations are free.
    BoundaryConditions(const Model& model, const std::vector<std::uint8_t>& full_rotation);

    [[nodiscard]] const std::array<bool, 6>& fixed(std::size_t p) const { return fixed_[p]; }
    /// Whether some translation component of particle p is prescribed.
    [[nodiscard]] bool prescribed_translation(std::size_t p) const {
        return prescribed_translation_[p] != 0;
    }
    /// u with the fixed and prescribed translation components of particle p set to zero.
    [[nodiscard]] Vec3 without_constrained_translation(std::size_t p, Vec3 u) const {
        for (Eigen::Index d = 0; d < 3; ++d)
            if (fixed_[p][static_cast<std::size_t>(d)] || prescribed_component(p, d)) u[d] = 0;
        return u;
    }
    /// `free` in the translation components of particle p that are not prescribed, `kept` in
    /// those that are.
    [[nodiscard]] Vec3 where_not_prescribed(std::size_t p, const Vec3& free, Vec3 kept) const {
        for (Eigen::Index d = 0; d < 3; ++d)
            if (!prescribed_component(p, d)) kept[d] = free[d];
        return kept;
    }
    [[nodiscard]] bool prescribed_rotation(std::size_t p) const { return prescribed_rotation_[p]; }
    /// A fixed or prescribed component: the only particles with reactions.
    [[nodiscard]] bool constrained(std::size_t p) const { return constrained_[p]; }
    /// These particles have reactions too (those of driven rigid bodies, eq. 6.11-7), though
    /// none of their own components is held.
    void add_reactions(const std::vector<Index>& particles) {
        for (const Index p : particles) constrained_[static_cast<std::size_t>(p)] = 1;
    }
    [[nodiscard]] bool has_prescribed_motions() const { return !prescribed_.empty(); }

    /// u with the fixed translation components of particle p set to zero.
    [[nodiscard]] Vec3 without_fixed_translation(std::size_t p, Vec3 u) const {
        for (Eigen::Index d = 0; d < 3; ++d)
            if (fixed_[p][static_cast<std::size_t>(d)]) u[d] = 0;
        return u;
    }
    /// Whether particle p rotates in its tangent plane (§1.3, §6.6): not a kink particle and at
    /// most one rotation fixed. With two fixed (a symmetry plane) the rotation is about the
    /// free axis alone: the one-sided normal of a particle on a symmetry plane is tilted out of
    /// the plane, and projecting onto its tangent plane would block that axis too.
    [[nodiscard]] bool rotates_in_tangent_plane(std::size_t p) const { return tangent_plane_[p]; }
    /// w with its component along the normal n removed where particle p rotates in its tangent
    /// plane; w itself elsewhere.
    [[nodiscard]] Vec3 tangent_part(std::size_t p, const Vec3& w, const Vec3& n) const {
        return tangent_plane_[p] ? Vec3(w - w.dot(n) * n) : w;
    }
    /// Whether the tangent plane is particle p's only rotation constraint: a tangent vector
    /// then needs no further projection (it would change by rounding only).
    [[nodiscard]] bool tangent_plane_only(std::size_t p) const {
        return tangent_plane_[p] && n_fixed_rotations_[p] == 0;
    }
    /// w with the constrained rotation directions of particle p removed (Gram-Schmidt on the
    /// fly): the normal n where it rotates in its tangent plane, then the fixed rotation axes.
    [[nodiscard]] Vec3 without_constrained_rotation(std::size_t p, Vec3 w, const Vec3& n) const {
        std::array<Vec3, 4> dirs;
        int n_dirs = 0;
        if (tangent_plane_[p]) dirs[static_cast<std::size_t>(n_dirs++)] = n;
        for (std::size_t d = 0; d < 3; ++d)
            if (fixed_[p][3 + d])
                dirs[static_cast<std::size_t>(n_dirs++)] = Vec3::Unit(static_cast<Eigen::Index>(d));
        std::array<Vec3, 3> basis;
        int nb = 0;
        for (int i = 0; i < n_dirs && nb < 3; ++i) {
            Vec3 d = dirs[static_cast<std::size_t>(i)];
            for (int j = 0; j < nb; ++j)
                d -= d.dot(basis[static_cast<std::size_t>(j)]) * basis[static_cast<std::size_t>(j)];
            const Real len = d.norm();
            if (len > 1e-8) basis[static_cast<std::size_t>(nb++)] = d / len;
        }
        for (int j = 0; j < nb; ++j)
            w -= w.dot(basis[static_cast<std::size_t>(j)]) * basis[static_cast<std::size_t>(j)];
        return w;
    }
    /// The drill axis of particle p for the tangent-plane normal n (§2.6, eq. 2.6c): the axis
    /// about which its rotation increment is neither integrated nor constrained; zero where the
    /// increment is complete (a kink, a prescribed rotation, a clamp).
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

    /// Per particle and direction: 1 / m where free, 0 where fixed or prescribed (contact §8.3).
    [[nodiscard]] std::vector<Vec3> free_inverse_mass(const std::vector<Real>& mass) const;
    /// free_inverse_mass of particle p of mass m.
    [[nodiscard]] Vec3 free_inverse_mass(std::size_t p, Real mass) const;

    /// Imposes the prescribed velocities, displacements and angular velocities on v^{n+1/2},
    /// w^{n+1/2} (§6.7) and adds the reactions that impose them: m / (c1 dt_n) times the change
    /// made (J for rotations).
    void impose_prescribed_motions(ParticleState& s, const std::vector<Curve>& curves,
                                   const PrescribedMotionTimes& at);

    /// The rotation imposed so far on every particle with a prescribed angular velocity (state
    /// of a relaxation; in restart files).
    [[nodiscard]] std::vector<Vec3>& prescribed_rotation_applied() {
        return prescribed_rotation_applied_;
    }

private:
    struct Prescribed {
        Index particle;
        PrescribedKind kind;
        Vec3 value;
        Index curve;
        std::uint8_t components;  ///< bit d: translation component d is prescribed
    };
    [[nodiscard]] bool prescribed_component(std::size_t p, Eigen::Index d) const {
        return ((prescribed_translation_[p] >> d) & 1U) != 0;
    }
    /// What a particle's rotation increment lacks (eq. 2.6c): nothing (a kink, a prescribed
    /// rotation, a clamp), the rotation about its normal (tangent-plane rotations), or, on a
    /// symmetry plane that leaves one rotation free, the rotation about its normal turned into
    /// that plane.
    enum class DrillKind : std::uint8_t { None, Normal, InSymmetryPlane };

    std::vector<std::array<bool, 6>> fixed_;  ///< per particle, ux uy uz rx ry rz
    std::vector<std::uint8_t> prescribed_translation_, prescribed_rotation_, constrained_;
    std::vector<std::uint8_t> tangent_plane_;      ///< rotates in its tangent plane
    std::vector<std::uint8_t> n_fixed_rotations_;  ///< fixed rotation components
    std::vector<DrillKind> drill_kind_;
    std::vector<Eigen::Index> drill_free_axis_;  ///< InSymmetryPlane: the free rotation component
    std::vector<Prescribed> prescribed_;
    std::vector<Vec3> prescribed_rotation_applied_;
};

}  // namespace fpmshell
