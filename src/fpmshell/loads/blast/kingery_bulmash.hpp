// The Kingery-Bulmash air-blast fits (theory.md §6.13, eq. 6.13-1; Kingery & Bulmash 1984,
// ARBRL-TR-02555, as ConWep and UFC 3-340-02 tabulate them): the peak incident and normally
// reflected overpressures, their positive-phase impulses, the arrival time and the positive-
// phase duration of the shock of a TNT charge against the scaled distance Z = R / W^(1/3)
// (Hopkinson-Cranz scaling: at a given Z, pressures are the same for any mass W, impulses
// and times grow as W^(1/3)). Each quantity is log10 Y = sum_i c_i U^i, U = a + b log10 Z.
#pragma once

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// The burst: a spherical charge in free air (LS-DYNA's BLAST 2), or a hemispherical charge
/// on the ground, whose shock the ground reflects and reinforces (BLAST 1).
enum class BlastBurst { FreeAir, Surface };

/// The shock at one point, in SI units: pressures [Pa], impulses [Pa s], times [s].
struct BlastWave {
    Real incident_pressure = 0;   ///< Pso, side-on peak overpressure
    Real reflected_pressure = 0;  ///< Pr, normally reflected peak overpressure
    Real incident_impulse = 0;    ///< is, of the positive phase
    Real reflected_impulse = 0;   ///< ir, of the positive phase
    Real arrival_time = 0;        ///< ta, after the detonation
    Real duration = 0;            ///< t0, of the positive phase (of the incident wave)
};

/// The scaled distances [m/kg^(1/3)] the fits hold between: from the charge's surface (TNT
/// of density 1.6: 0.053 W^(1/3) m; 0.0674 for the hemisphere on the ground) to 40.
[[nodiscard]] Real kingery_bulmash_min_distance(BlastBurst burst);
constexpr Real k_kingery_bulmash_max_distance = 40.0;

/// The shock of `mass` kg of TNT at `distance` m (eq. 6.13-1). Inside the fits' lower bound
/// (or a quantity's own, where its fit starts further out) the values at that bound; beyond
/// 40 m/kg^(1/3), where the shock has become a weak acoustic wave, pressures and impulses
/// decay as 1/Z from their values at 40 and the front travels at the speed of sound
/// (eq. 6.13-2).
[[nodiscard]] BlastWave kingery_bulmash(BlastBurst burst, Real mass, Real distance);

}  // namespace fpmshell
