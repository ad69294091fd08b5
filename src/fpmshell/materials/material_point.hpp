// History stored at one integration point (in-plane point g, thickness point k) of an element.
// Components are in the convected element frame (theory.md §2.7), so they need no rotation.
#pragma once

#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct MaterialPoint {
    Voigt3 stress = Voigt3::Zero();       ///< [sxx, syy, sxy]
    Voigt3 back_stress = Voigt3::Zero();  ///< b of theory.md §7.2 (kinematic hardening)
    Real plastic_strain = 0;              ///< equivalent plastic strain alpha (§7.2)
    Real plastic_work = 0;                ///< plastic work per unit volume, sum of sigma . d_eps_p
    Real strain_rate = 0;                 ///< filtered effective total strain rate (§7.4 option a)
    /// kappa(alpha) / R of §7.4, the yield radius at the reference rate, stored when alpha
    /// grows so that an elastic step needs no flow-curve evaluation (read only once alpha > 0).
    Real flow_radius = 0;
    Real flow_slope = 0;  ///< sigma_f'(alpha), stored with flow_radius (the next step's H_k)
};

/// Members of a material point for a restart file (io/restart_archive.hpp).
template <class Archive>
void transfer(Archive& ar, MaterialPoint& p) {
    ar(p.stress, p.back_stress, p.plastic_strain, p.plastic_work, p.strain_rate, p.flow_radius,
       p.flow_slope);
}

}  // namespace fpmshell
