// J2 plasticity with isotropic damage (theory.md eq. 7.6-4; LS-DYNA's *MAT_081/082
// PLASTICITY_WITH_DAMAGE): the J2 law of materials/j2 runs on the effective (undamaged) stress,
// and the point carries the nominal stress sigma = (1 - D) sigma_eff, D rising linearly in the
// plastic strain from 0 at `start` (EPPF) to 1 at `rupture` (EPPFR), where the point carries
// nothing. Its point: the nominal stress, then the J2 point of the effective stress (3 + 11
// numbers); computed element by element (no SIMD block path).
#pragma once

#include <algorithm>

#include "fpmshell/materials/j2/j2_plastic.hpp"
#include "fpmshell/materials/material_point.hpp"

namespace fpmshell {

class PlasticDamage {
public:
    struct Point {
        Voigt3 stress = Voigt3::Zero();  ///< nominal
        MaterialPoint effective;         ///< the J2 point, its stress the effective one
        Real plastic_strain = 0;         ///< effective.plastic_strain (for the output)
        Real plastic_work = 0;           ///< effective.plastic_work
    };

    PlasticDamage(const J2Plastic& j2, Real start, Real rupture)
        : j2_(j2), start_(start), rupture_(rupture) {}

    [[nodiscard]] const Mat3& stiffness() const { return j2_.stiffness(); }
    [[nodiscard]] Real youngs_modulus() const { return j2_.youngs_modulus(); }
    [[nodiscard]] Real poisson_ratio() const { return j2_.poisson_ratio(); }

    /// D at plastic strain alpha (eq. 7.6-4).
    [[nodiscard]] Real damage(Real alpha) const {
        return std::clamp((alpha - start_) / (rupture_ - start_), 0.0, 1.0);
    }

    void update(const Point& old_state, const Voigt3& d_eps, Real dt, Point& new_state) const {
        j2_.update(old_state.effective, d_eps, dt, new_state.effective);
        const MaterialPoint& e = new_state.effective;
        new_state.stress = (1.0 - damage(e.plastic_strain)) * e.stress;
        new_state.plastic_strain = e.plastic_strain;
        new_state.plastic_work = e.plastic_work;
    }

    // The layout (solver/element_group.hpp): the nominal stress, then the J2 point's fields.
    static constexpr std::size_t k_j2 = 3;
    static constexpr std::size_t k_point_fields = k_j2 + J2Plastic::k_point_fields;
    static constexpr bool k_stress_only = false;
    static constexpr std::size_t k_stress = 0,
                                 k_plastic_strain = k_j2 + J2Plastic::k_plastic_strain,
                                 k_plastic_work = k_j2 + J2Plastic::k_plastic_work;
    template <class Field>
    [[nodiscard]] Point read_point(const Field& field) const {
        Point p;
        p.stress = Voigt3(field(0), field(1), field(2));
        p.effective = j2_.read_point([&](std::size_t k) { return field(k_j2 + k); });
        p.plastic_strain = p.effective.plastic_strain;
        p.plastic_work = p.effective.plastic_work;
        return p;
    }
    template <class Set>
    void write_point(const Point& p, const Set& set) const {
        for (std::size_t r = 0; r < 3; ++r) set(r, p.stress(static_cast<Eigen::Index>(r)));
        j2_.write_point(p.effective, [&](std::size_t k, Real v) { set(k_j2 + k, v); });
    }
    [[nodiscard]] Real initial_field(std::size_t k) const {
        return k < k_j2 ? 0.0 : j2_.initial_field(k - k_j2);
    }

private:
    J2Plastic j2_;
    Real start_, rupture_;
};

}  // namespace fpmshell
