#include "fpmshell/loads/blast/blast_load.hpp"

#include <limits>

#include "fpmshell/core/simd_math.hpp"

namespace fpmshell {

Real blast_incidence_pressure(Real incident, Real reflected, Real cos_theta) {
    if (!(cos_theta > 0)) return incident;
    const Real c2 = cos_theta * cos_theta;
    return reflected * c2 + incident * (1.0 + cos_theta - 2.0 * c2);
}

BlastFaces::BlastFaces(const BlastLoad& load, const std::vector<Vec3>& nodes,
                       const std::vector<std::array<Index, 3>>& triangles)
    : detonation_time_(load.detonation_time),
      death_time_(load.death_time),
      negative_phase_(load.negative_phase) {
    const Real pascals = load.kilograms / (load.metres * load.seconds * load.seconds);
    floor_ = -k_ambient_pressure / pascals;
    for (const Index e : load.elements) {
        const auto& t = triangles[static_cast<std::size_t>(e)];
        const Vec3 centroid =
            (nodes[static_cast<std::size_t>(t[0])] + nodes[static_cast<std::size_t>(t[1])] +
             nodes[static_cast<std::size_t>(t[2])]) /
            3.0;
        const BlastWave w = kingery_bulmash(load.burst, load.charge_mass * load.kilograms,
                                            (centroid - load.centre).norm() * load.metres);
        arrival_.push_back(w.arrival_time / load.seconds);
        duration_.push_back(w.duration / load.seconds);
        incident_.push_back(load.scale * w.incident_pressure / pascals);
        reflected_.push_back(load.scale * w.reflected_pressure / pascals);
        // eq. 6.13-3: each pulse's decay from its own impulse (SI, as the fits)
        incident_decay_.push_back(
            friedlander_decay(w.incident_pressure, w.duration, w.incident_impulse));
        reflected_decay_.push_back(
            friedlander_decay(w.reflected_pressure, w.duration, w.reflected_impulse));
    }
    // whole packs: the padding faces never arrive
    const std::size_t n = load.elements.size();
    const std::size_t padded = (n + k_lanes - 1) / k_lanes * k_lanes;
    arrival_.resize(padded, std::numeric_limits<Real>::infinity());
    for (auto* v : {&duration_, &incident_, &reflected_, &incident_decay_, &reflected_decay_})
        v->resize(padded, 1.0);
    faces_ = n;
}

RealPack BlastFaces::pressures(std::size_t k, Real t, const RealPack& cos_theta) const {
    if (t >= death_time_) return RealPack(0.0);
    auto at = [&](const std::vector<Real>& v) {
        return RealPack(v.data() + k, stdx::element_aligned);
    };
    const RealPack duration = at(duration_);
    const RealPack tau = RealPack(t - detonation_time_) - at(arrival_);
    const auto positive = tau <= duration;
    auto live = tau >= 0.0;
    if (!negative_phase_) live = live && positive;
    if (!any_lane(live)) return RealPack(0.0);
    const RealPack x = select(live, tau / duration, RealPack(0.0));
    const RealPack fall = 1.0 - x;
    // eq. 6.13-5: past its positive phase a pulse of decay b <= 0 has no negative phase
    auto pulse = [&](const std::vector<Real>& peak, const std::vector<Real>& decay) {
        const RealPack b = at(decay);
        const RealPack p = at(peak) * fall * vector_exp(-b * x);
        return negative_phase_ ? select(positive || b > 0.0, p, RealPack(0.0)) : p;
    };
    const RealPack incident = pulse(incident_, incident_decay_);
    const RealPack reflected = pulse(reflected_, reflected_decay_);
    // eq. 6.13-4
    const RealPack c2 = cos_theta * cos_theta;
    const RealPack seen = reflected * c2 + incident * (1.0 + cos_theta - 2.0 * c2);
    const RealPack p = select(cos_theta > 0.0, seen, incident);
    return select(live, negative_phase_ ? max(p, RealPack(floor_)) : p, RealPack(0.0));
}

}  // namespace fpmshell
