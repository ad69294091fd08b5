// A material law that lives only in the tests: linear elasticity softened by isotropic damage,
// sigma = (1 - d(kappa)) C eps, kappa the largest strain norm sqrt(eps : eps) the point has
// seen, d = (1 - r)(1 - kappa_0 / kappa) past kappa_0 (d -> 1 - r: the point keeps the
// fraction r of its stiffness). Its point keeps its own state, the total strain and kappa
// besides the stress, in a layout of its own (7 numbers).
//
// It shows the materials seam (src/fpmshell/materials/material_law.hpp): this folder and its
// one registry line (damaging_elastic_law.cpp) make a law that a model file names, whose state
// survives a restart and the transfer between ranks, with no change anywhere else.
#pragma once

#include <algorithm>
#include <cmath>

#include "fpmshell/core/types.hpp"
#include "fpmshell/materials/elastic/linear_elastic.hpp"

namespace fpmshell::test {

/// The law's constants (Material::parameters).
struct DamagingElasticParameters {
    Real damage_strain = 0;      ///< kappa_0
    Real residual_fraction = 1;  ///< r, in (0, 1]
};

class DamagingElastic {
public:
    struct Point {
        Voigt3 stress = Voigt3::Zero();
        Voigt3 strain = Voigt3::Zero();  ///< total strain, engineering shear
        Real kappa = 0;                  ///< the largest strain norm so far
    };

    DamagingElastic(Real youngs_modulus, Real poisson_ratio, const DamagingElasticParameters& p)
        : e_(youngs_modulus),
          nu_(poisson_ratio),
          p_(p),
          c_(LinearElastic(youngs_modulus, poisson_ratio).stiffness()) {}
    [[nodiscard]] const Mat3& stiffness() const { return c_; }
    [[nodiscard]] Real youngs_modulus() const { return e_; }
    [[nodiscard]] Real poisson_ratio() const { return nu_; }

    /// d(kappa)
    [[nodiscard]] Real damage(Real kappa) const {
        if (!(kappa > p_.damage_strain)) return 0;
        return (1.0 - p_.residual_fraction) * (1.0 - p_.damage_strain / kappa);
    }
    /// sqrt(eps : eps) with the engineering shear strain gamma = 2 eps_12
    [[nodiscard]] static Real strain_norm(const Voigt3& eps) {
        return std::sqrt(eps(0) * eps(0) + eps(1) * eps(1) + 0.5 * eps(2) * eps(2));
    }

    void update(const Point& old_state, const Voigt3& d_eps, Real /*dt*/, Point& new_state) const {
        const Voigt3 strain = old_state.strain + d_eps;
        const Real kappa = std::max(old_state.kappa, strain_norm(strain));
        new_state.strain = strain;
        new_state.kappa = kappa;
        new_state.stress = (1.0 - damage(kappa)) * (c_ * strain);
    }

    // The layout of a point (solver/element_group.hpp): stress, strain, kappa.
    static constexpr std::size_t k_point_fields = 7;
    static constexpr bool k_stress_only = false;
    template <class Field>
    [[nodiscard]] Point read_point(const Field& field) const {
        Point p;
        p.stress = Voigt3(field(0), field(1), field(2));
        p.strain = Voigt3(field(3), field(4), field(5));
        p.kappa = field(6);
        return p;
    }
    template <class Set>
    void write_point(const Point& p, const Set& set) const {
        for (std::size_t r = 0; r < 3; ++r) {
            set(r, p.stress(static_cast<Eigen::Index>(r)));
            set(3 + r, p.strain(static_cast<Eigen::Index>(r)));
        }
        set(6, p.kappa);
    }
    [[nodiscard]] Real initial_field(std::size_t /*k*/) const { return 0; }

private:
    Real e_, nu_;
    DamagingElasticParameters p_;
    Mat3 c_;
};

}  // namespace fpmshell::test
