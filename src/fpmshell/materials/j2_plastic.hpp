// Elastic-plastic material in plane stress: von Mises yield with mixed isotropic / kinematic
// hardening, a linear or Johnson-Cook flow curve and an optional strain-rate factor; return
// mapping in the plane-stress subspace (theory.md §7, Simo & Taylor 1986).
#pragma once

#include "fpmshell/core/types.hpp"
#include "fpmshell/materials/flow_stress.hpp"
#include "fpmshell/materials/j2_return_mapping.hpp"
#include "fpmshell/materials/material_point.hpp"

namespace fpmshell {

class J2Plastic {
public:
    /// A trial state is elastic when F <= tol kappa^2 / 3, and the return mapping has
    /// converged when |F| < tol kappa^2 / 3 (§7.3 steps 1 and 3).
    static constexpr Real k_yield_tolerance = 1e-10;
    /// Exponential filter of the strain rate, rate_f <- chi rate + (1 - chi) rate_f: a memory of
    /// about 1 / chi = 10 steps removes the step-to-step noise of the explicit rate (theory.md
    /// §7.4 option a; the Fcut filter of Radioss LAW2 plays the same role).
    static constexpr Real k_rate_filter = 0.1;

    /// hardening_mix: beta of §7.2, 1 isotropic, 0 kinematic.
    J2Plastic(Real youngs_modulus, Real poisson_ratio, const FlowStress& flow, const RateFactor& rate,
              Real hardening_mix);

    /// Elastic plane-stress matrix C (engineering shear strain).
    [[nodiscard]] const Mat3& stiffness() const { return c_; }
    [[nodiscard]] Real youngs_modulus() const { return e_; }
    [[nodiscard]] Real poisson_ratio() const { return nu_; }

    /// New state of a point from its old state, the strain increment d_eps over the step dt
    /// (dt is used for the strain rate only). old_state and new_state may be the same object.
    void update(const MaterialPoint& old_state, const Voigt3& d_eps, Real dt, MaterialPoint& new_state) const;

    /// Radius kappa(alpha) of the yield surface (uniaxial yield stress) at the rate factor r.
    [[nodiscard]] Real yield_radius(Real alpha, Real r) const;
    /// kappa / R before any plastic strain: the flow curve at alpha = 0.
    [[nodiscard]] Real initial_flow_radius() const { return flow_.value(0); }
    /// Whether the yield radius depends on the strain rate (then every update filters the rate).
    [[nodiscard]] bool rate_dependent() const { return rate_.active(); }
    [[nodiscard]] const RateFactor& rate_factor() const { return rate_; }
    /// The constants of the return mapping (materials/j2_return_mapping.hpp), for the element
    /// blocks that run it on k_lanes points at once.
    [[nodiscard]] const J2ReturnConstants& return_constants() const { return constants_; }

private:
    Real e_, nu_;
    Mat3 c_;
    FlowStress flow_;
    RateFactor rate_;
    Real beta_;
    J2ReturnConstants constants_;
};

/// Effective total strain rate of a plane-stress increment (§7.4 option a, incompressible
/// estimate, engineering shear in, tensor shear inside).
[[nodiscard]] Real effective_strain_rate(const Voigt3& d_eps, Real dt);

}  // namespace fpmshell
