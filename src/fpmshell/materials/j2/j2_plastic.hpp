// Elastic-plastic material in plane stress: von Mises yield with mixed isotropic / kinematic
// hardening, a linear, Johnson-Cook or tabulated flow curve and an optional strain-rate factor
// (or a table of curves at increasing rates); return
// mapping in the plane-stress subspace (theory.md §7, Simo & Taylor 1986).
#pragma once

#include "fpmshell/core/types.hpp"
#include "fpmshell/materials/j2/flow_stress.hpp"
#include "fpmshell/materials/j2/j2_return_mapping.hpp"
#include "fpmshell/materials/j2/strain_rate.hpp"
#include "fpmshell/materials/j2/thermal_softening.hpp"
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
    /// normal_anisotropy: Hill's R (the Lankford ratio of width to thickness strain, the same
    /// in every direction of the sheet, eq. 7.1-3); 1 is von Mises.
    /// thermal: Johnson-Cook's softening by adiabatic heating (eq. 7.4-2), a factor on the
    /// yield radius like the rate factor's, at the temperature of the step's start.
    J2Plastic(Real youngs_modulus, Real poisson_ratio, const FlowStress& flow,
              const RateFactor& rate, Real hardening_mix, Real normal_anisotropy = 1,
              const ThermalSoftening& thermal = {});

    /// Elastic plane-stress matrix C (engineering shear strain).
    [[nodiscard]] const Mat3& stiffness() const { return c_; }
    [[nodiscard]] Real youngs_modulus() const { return e_; }
    [[nodiscard]] Real poisson_ratio() const { return nu_; }

    /// New state of a point from its old state, the strain increment d_eps over the step dt
    /// (dt is used for the strain rate only). old_state and new_state may be the same object.
    void update(const MaterialPoint& old_state, const Voigt3& d_eps, Real dt,
                MaterialPoint& new_state) const;

    /// The state a point keeps between steps, as the element groups store it
    /// (solver/element_group.hpp): k_point_fields numbers, read and written through
    /// field(k) and set(k, value), one field per component.
    static constexpr std::size_t k_stress = 0, k_back_stress = 3, k_plastic_strain = 6,
                                 k_plastic_work = 7, k_strain_rate = 8, k_flow_radius = 9,
                                 k_flow_slope = 10;
    static constexpr std::size_t k_point_fields = 11;
    static constexpr bool k_stress_only = false;
    template <class Field>
    [[nodiscard]] MaterialPoint read_point(const Field& field) const {
        MaterialPoint mp;
        mp.stress = Voigt3(field(k_stress), field(k_stress + 1), field(k_stress + 2));
        mp.back_stress =
            Voigt3(field(k_back_stress), field(k_back_stress + 1), field(k_back_stress + 2));
        mp.plastic_strain = field(k_plastic_strain);
        mp.plastic_work = field(k_plastic_work);
        mp.strain_rate = field(k_strain_rate);
        mp.flow_radius = field(k_flow_radius);
        mp.flow_slope = field(k_flow_slope);
        return mp;
    }
    /// The stored flow radius is valid before the first yield too: sigma_f(0) until the point
    /// first yields (the material point's own convention is 0 with alpha = 0, which the
    /// return mapping reads as sigma_f(0)), so that the trial check of a block reads the
    /// radius alone, not the plastic strain too.
    template <class Set>
    void write_point(const MaterialPoint& mp, const Set& set) const {
        for (std::size_t r = 0; r < 3; ++r)
            set(k_stress + r, mp.stress(static_cast<Eigen::Index>(r)));
        for (std::size_t r = 0; r < 3; ++r)
            set(k_back_stress + r, mp.back_stress(static_cast<Eigen::Index>(r)));
        set(k_plastic_strain, mp.plastic_strain);
        set(k_plastic_work, mp.plastic_work);
        set(k_strain_rate, mp.strain_rate);
        set(k_flow_radius, mp.plastic_strain > 0 ? mp.flow_radius : initial_flow_radius());
        set(k_flow_slope, mp.flow_slope);
    }
    /// The value of field k before the first step.
    [[nodiscard]] Real initial_field(std::size_t k) const {
        return k == k_flow_radius ? initial_flow_radius() : 0;
    }

    /// Radius kappa(alpha) of the yield surface (uniaxial yield stress) at the rate factor r
    /// (for a rate table: at the position r among its rates, FlowTable::position).
    [[nodiscard]] Real yield_radius(Real alpha, Real r) const;
    /// kappa / R before any plastic strain: the flow curve at alpha = 0.
    [[nodiscard]] Real initial_flow_radius() const { return flow_.value(0); }
    /// Whether the yield radius depends on the strain rate (then every update filters the rate).
    [[nodiscard]] bool rate_dependent() const { return rate_.active(); }
    [[nodiscard]] const RateFactor& rate_factor() const { return rate_; }
    [[nodiscard]] const ThermalSoftening& thermal_softening() const { return thermal_; }
    /// The constants of the return mapping (materials/j2_return_mapping.hpp), for the element
    /// blocks that run it on k_lanes points at once.
    [[nodiscard]] const J2ReturnConstants& return_constants() const { return constants_; }

private:
    Real e_, nu_;
    Mat3 c_;
    FlowStress flow_;
    RateFactor rate_;
    ThermalSoftening thermal_;
    Real beta_;
    J2ReturnConstants constants_;
};

}  // namespace fpmshell
