#include "fpmshell/solver/boundary_conditions.hpp"

#include <algorithm>

namespace fpmshell {

BoundaryConditions::BoundaryConditions(const Model& model,
                                       const std::vector<std::uint8_t>& full_rotation) {
    const std::size_t np = model.nodes.size();
    fixed_.assign(np, {});
    prescribed_translation_.assign(np, 0);
    prescribed_rotation_.assign(np, 0);
    prescribed_rotation_applied_.assign(np, Vec3::Zero());
    for (const BoundaryCondition& bc : model.boundary) {
        for (Index p : bc.nodes) {
            const std::size_t up = static_cast<std::size_t>(p);
            for (std::size_t d = 0; d < 6; ++d) fixed_[up][d] = fixed_[up][d] || bc.fixed[d];
            if (bc.prescribed != PrescribedKind::None) {
                std::uint8_t components = 0;
                for (std::size_t d = 0; d < 3; ++d)
                    if (bc.components[d]) components |= static_cast<std::uint8_t>(1U << d);
                prescribed_.push_back({p, bc.prescribed, bc.value, bc.curve, components});
                if (bc.prescribed == PrescribedKind::AngularVelocity)
                    prescribed_rotation_[up] = 1;
                else
                    prescribed_translation_[up] |= components;
            }
        }
    }
    constrained_.assign(np, 0);
    tangent_plane_.assign(np, 0);
    n_fixed_rotations_.assign(np, 0);
    drill_kind_.assign(np, DrillKind::None);
    drill_free_axis_.assign(np, 0);
    for (std::size_t p = 0; p < np; ++p) {
        constrained_[p] = prescribed_translation_[p] || prescribed_rotation_[p] ||
                          std::any_of(fixed_[p].begin(), fixed_[p].end(), [](bool f) { return f; });
        const int n_fixed_rot = fixed_[p][3] + fixed_[p][4] + fixed_[p][5];
        n_fixed_rotations_[p] = static_cast<std::uint8_t>(n_fixed_rot);
        tangent_plane_[p] = !full_rotation[p] && n_fixed_rot < 2;
        // §2.6 eq. 2.6c: the rotation the update leaves out. A prescribed rotation is complete
        // (it is imposed after the update, about a fixed axis).
        if (prescribed_rotation_[p] || full_rotation[p] || n_fixed_rot == 3) continue;
        if (tangent_plane_[p]) {
            drill_kind_[p] = DrillKind::Normal;
        } else {
            drill_kind_[p] = DrillKind::InSymmetryPlane;
            for (Eigen::Index d = 0; d < 3; ++d)
                if (!fixed_[p][3 + static_cast<std::size_t>(d)]) drill_free_axis_[p] = d;
        }
    }
}

std::vector<Vec3> BoundaryConditions::free_inverse_mass(const std::vector<Real>& mass) const {
    std::vector<Vec3> inv_mass(mass.size());
    for (std::size_t p = 0; p < mass.size(); ++p) inv_mass[p] = free_inverse_mass(p, mass[p]);
    return inv_mass;
}

Vec3 BoundaryConditions::free_inverse_mass(std::size_t p, Real mass) const {
    Vec3 inv_mass = Vec3::Zero();
    if (!(mass > 0)) return inv_mass;
    for (Eigen::Index d = 0; d < 3; ++d)
        if (!fixed_[p][static_cast<std::size_t>(d)] && !prescribed_component(p, d))
            inv_mass[d] = 1.0 / mass;
    return inv_mass;
}

void BoundaryConditions::impose_prescribed_motions(ParticleState& s,
                                                   const std::vector<Curve>& curves,
                                                   const PrescribedMotionTimes& at) {
    for (const Prescribed& pr : prescribed_) {
        const std::size_t p = static_cast<std::size_t>(pr.particle);
        if (pr.kind ==
            PrescribedKind::AngularVelocity) {  // about a fixed axis, no tangent-plane projection
            const Vec3 omega_before = s.omega[p];
            if (at.relaxation) {
                const Vec3 target =
                    curve_factor_integral(curves, pr.curve, at.load_time) * pr.value;
                s.omega[p] = (target - prescribed_rotation_applied_[p]) / at.dt_new;
            } else {
                s.omega[p] = curve_factor(curves, pr.curve, at.t_half) * pr.value;
            }
            prescribed_rotation_applied_[p] += at.dt_new * s.omega[p];
            s.reaction_moment[p] +=
                (s.inertia[p] / (at.c1 * at.dt_n)) * (s.omega[p] - omega_before);
            continue;
        }
        const Vec3 v_before = s.v[p];
        Vec3 v_imposed;
        if (pr.kind == PrescribedKind::Acceleration) {  // v^{n+1/2} = v^{n-1/2} + dt_n a(t_n)
            v_imposed =
                s.v_prev[p] + (at.dt_n * curve_factor(curves, pr.curve, at.load_time)) * pr.value;
        } else if (pr.kind == PrescribedKind::Velocity && !at.relaxation) {
            v_imposed = curve_factor(curves, pr.curve, at.t_half) * pr.value;
        } else {  // a displacement, or in relaxation the integral of a velocity
            const Real factor = pr.kind == PrescribedKind::Velocity
                                    ? curve_factor_integral(curves, pr.curve, at.load_time)
                                    : curve_factor(curves, pr.curve, at.t_next);
            const Vec3 target = s.x0[p] + factor * pr.value;
            v_imposed = (target - s.x[p]) / at.dt_new;
        }
        for (Eigen::Index d = 0; d < 3; ++d)  // only the entry's components
            if (((pr.components >> d) & 1U) != 0) s.v[p][d] = v_imposed[d];
        s.reaction[p] += (s.mass[p] / (at.c1 * at.dt_n)) * (s.v[p] - v_before);
    }
}

}  // namespace fpmshell
