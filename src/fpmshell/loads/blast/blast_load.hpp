// An air blast on a set of faces (theory.md §6.13; LS-DYNA's *LOAD_BLAST_ENHANCED, OpenRadioss's
// /LOAD/PBLAST): each face takes, from its distance to the charge, the Kingery-Bulmash shock
// (kingery_bulmash.hpp) as two Friedlander pulses (friedlander_pulse.hpp), incident and
// normally reflected, arriving at the face's arrival time; at each step they are combined by
// the angle of incidence between the face's current normal and the line from its centroid
// to the charge (eq. 6.13-4) and act as a pressure on the face's current area. With the
// negative phase, each pulse continues past its positive phase (eq. 6.13-5) and the pressure
// never falls below the vacuum's, -p_ambient.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/core/types.hpp"
#include "fpmshell/loads/blast/friedlander_pulse.hpp"
#include "fpmshell/loads/blast/kingery_bulmash.hpp"

namespace fpmshell {

/// One `loads` entry of type blast (model units unless said).
struct BlastLoad {
    std::vector<Index> elements;  ///< the faces loaded
    BlastBurst burst = BlastBurst::FreeAir;
    Real charge_mass = 0;        ///< TNT equivalent
    Vec3 centre = Vec3::Zero();  ///< the charge's centre
    Real detonation_time = 0;
    Real death_time = std::numeric_limits<Real>::infinity();  ///< no pressure from then on
    Real scale = 1;                                           ///< a factor on the pressure
    /// the faces' normal against their elements' (a segment listed in the other order): it
    /// decides which side sees the charge and the pressure pushes against it
    bool reversed = false;
    /// eq. 6.13-5: the pulses continued past their positive phase as LS-DYNA's NEGPHS 0 (off:
    /// the positive phase only, NEGPHS 1)
    bool negative_phase = false;
    /// the model's units in SI: metres, kilograms, seconds per model unit
    Real metres = 1, kilograms = 1, seconds = 1;
};

/// eq. 6.13-4 (Randers-Pehrson & Bannister 1997): the pressure on a face whose normal makes
/// the angle theta with the line to the charge, cos_theta > 0 (it sees the charge):
/// Pr cos^2 + Pso (1 + cos - 2 cos^2); a face that does not see it: Pso.
[[nodiscard]] Real blast_incidence_pressure(Real incident, Real reflected, Real cos_theta);

/// The pulses of a blast's faces, set from their initial centroids.
class BlastFaces {
public:
    /// nodes, triangles: the model's initial mesh.
    BlastFaces(const BlastLoad& load, const std::vector<Vec3>& nodes,
               const std::vector<std::array<Index, 3>>& triangles);

    [[nodiscard]] std::size_t size() const { return faces_; }
    /// The pressure on face k (of load.elements) at time t (model units), whose current
    /// normal makes the angle theta with the line from its centroid to the charge.
    [[nodiscard]] Real pressure(std::size_t k, Real t, Real cos_theta) const {
        if (t >= death_time_) return 0.0;
        const Real tau = t - detonation_time_ - arrival_[k];
        if (tau < 0 || (tau > duration_[k] && !negative_phase_)) return 0.0;
        const Real p = blast_incidence_pressure(
            friedlander_pressure(incident_[k], duration_[k], incident_decay_[k], tau,
                                 negative_phase_),
            friedlander_pressure(reflected_[k], duration_[k], reflected_decay_[k], tau,
                                 negative_phase_),
            cos_theta);
        return negative_phase_ ? std::max(p, floor_) : p;
    }
    /// The same of the k_lanes faces from k on (past size(): 0), a pack at a time: the two
    /// pulses by vector_exp (core/simd_math.hpp: a lane's bits do not depend on its place).
    [[nodiscard]] RealPack pressures(std::size_t k, Real t, const RealPack& cos_theta) const;
    /// The pulses' times of face k: its arrival and its positive phase (model units).
    [[nodiscard]] Real arrival(std::size_t k) const { return arrival_[k]; }
    [[nodiscard]] Real duration(std::size_t k) const { return duration_[k]; }
    /// Whether the pulses go on past their positive phase (eq. 6.13-5).
    [[nodiscard]] bool negative_phase() const { return negative_phase_; }
    /// The standard atmosphere's pressure, 101 325 Pa: the deepest suction is -p_ambient.
    static constexpr Real k_ambient_pressure = 101325.0;

private:
    // per face, model units (padded with faces that never arrive to whole packs)
    std::vector<Real> arrival_, duration_, incident_, reflected_, incident_decay_, reflected_decay_;
    std::size_t faces_ = 0;
    Real detonation_time_, death_time_;
    bool negative_phase_;
    Real floor_;  ///< -p_ambient in model units, where the negative phase is on
};

}  // namespace fpmshell
