#include "fpmshell/loads/blast/blast_load.hpp"

#include "fpmshell/loads/blast/friedlander_pulse.hpp"

namespace fpmshell {

Real blast_incidence_pressure(Real incident, Real reflected, Real cos_theta) {
    if (!(cos_theta > 0)) return incident;
    const Real c2 = cos_theta * cos_theta;
    return reflected * c2 + incident * (1.0 + cos_theta - 2.0 * c2);
}

BlastFaces::BlastFaces(const BlastLoad& load, const std::vector<Vec3>& nodes,
                       const std::vector<std::array<Index, 3>>& triangles)
    : detonation_time_(load.detonation_time), death_time_(load.death_time) {
    const Real pascals = load.kilograms / (load.metres * load.seconds * load.seconds);
    faces_.reserve(load.elements.size());
    for (const Index e : load.elements) {
        const auto& t = triangles[static_cast<std::size_t>(e)];
        const Vec3 centroid =
            (nodes[static_cast<std::size_t>(t[0])] + nodes[static_cast<std::size_t>(t[1])] +
             nodes[static_cast<std::size_t>(t[2])]) /
            3.0;
        const BlastWave w = kingery_bulmash(load.burst, load.charge_mass * load.kilograms,
                                            (centroid - load.centre).norm() * load.metres);
        Face f;
        f.arrival = w.arrival_time / load.seconds;
        f.duration = w.duration / load.seconds;
        f.incident = load.scale * w.incident_pressure / pascals;
        f.reflected = load.scale * w.reflected_pressure / pascals;
        // eq. 6.13-3: each pulse's decay from its own impulse (SI, as the fits)
        f.incident_decay = friedlander_decay(w.incident_pressure, w.duration, w.incident_impulse);
        f.reflected_decay =
            friedlander_decay(w.reflected_pressure, w.duration, w.reflected_impulse);
        faces_.push_back(f);
    }
}

Real BlastFaces::pressure(std::size_t k, Real t, Real cos_theta) const {
    if (t >= death_time_) return 0.0;
    const Face& f = faces_[k];
    const Real tau = t - detonation_time_ - f.arrival;
    if (tau < 0 || tau > f.duration) return 0.0;
    return blast_incidence_pressure(
        friedlander_pressure(f.incident, f.duration, f.incident_decay, tau),
        friedlander_pressure(f.reflected, f.duration, f.reflected_decay, tau), cos_theta);
}

}  // namespace fpmshell
