// Isotropic linear elastic material in plane stress (theory.md §3.2), incremental form:
// sigma_{n+1} = sigma_n + C d_eps (engineering stress on the convected frame of the path element).
#pragma once

#include "fpmshell/core/types.hpp"
#include "fpmshell/materials/material_point.hpp"

namespace fpmshell {

class LinearElastic {
public:
    LinearElastic(Real youngs_modulus, Real poisson_ratio)
        : e_(youngs_modulus), nu_(poisson_ratio) {
        const Real f = e_ / (1.0 - nu_ * nu_);
        c_ << f, f * nu_, 0, f * nu_, f, 0, 0, 0, f * (1.0 - nu_) * 0.5;
    }

    /// Plane-stress elasticity matrix C (engineering shear strain).
    [[nodiscard]] const Mat3& stiffness() const { return c_; }
    [[nodiscard]] Real youngs_modulus() const { return e_; }
    [[nodiscard]] Real poisson_ratio() const { return nu_; }

    /// The state a point keeps between steps, as the element groups store it
    /// (solver/element_group.hpp): k_point_fields numbers, read and written through
    /// field(k) and set(k, value). An elastic point keeps its stress only.
    static constexpr std::size_t k_point_fields = 3;
    /// The state is a stress only (restart files keep such points apart).
    static constexpr bool k_stress_only = true;
    template <class Field>
    [[nodiscard]] MaterialPoint read_point(const Field& field) const {
        MaterialPoint mp;
        mp.stress = Voigt3(field(0), field(1), field(2));
        return mp;
    }
    template <class Set>
    void write_point(const MaterialPoint& mp, const Set& set) const {
        for (std::size_t r = 0; r < 3; ++r) set(r, mp.stress(static_cast<Eigen::Index>(r)));
    }
    /// The value of field k before the first step.
    [[nodiscard]] Real initial_field(std::size_t /*k*/) const { return 0; }

    /// New state of a point from its old state and the strain increment d_eps.
    void update(const MaterialPoint& old_state, const Voigt3& d_eps, Real /*dt*/,
                MaterialPoint& new_state) const {
        new_state.stress = old_state.stress + c_ * d_eps;
    }

private:
    Real e_, nu_;
    Mat3 c_;
};

}  // namespace fpmshell
