// Erosion in the element loop (theory.md §7.6): which elements have eroded, the booking of
// their work, and the check after each element's step.
#include "fpmshell/solver/shell_elements.hpp"

namespace fpmshell {

std::vector<Index> ShellElements::eroded_in_last_step() const {
    std::vector<Index> out;
    for (std::size_t e = 0; e < eroded_.size(); ++e)
        if (eroded_[e] == k_eroded_pending) out.push_back(static_cast<Index>(e));
    return out;
}

std::vector<Index> ShellElements::eroded_so_far() const {
    std::vector<Index> out;
    for (std::size_t e = 0; e < eroded_.size(); ++e)
        if (eroded_[e] != 0) out.push_back(static_cast<Index>(e));
    return out;
}

// The loads of the step an element erodes in stand (the particles take them over the next
// half step); the element's work over that half step, 1/2 f . dx + 1/2 m . dtheta (the second
// half of the trapezoid eq. 6.8-1 books for its loads), is booked one step later from them.
void ShellElements::book_last_half_step(std::size_t e, const ParticleState& s, ElementTotals& t) {
    if (eroded_[e] != k_eroded_pending) return;
    const std::array<Real, 18>& loads = last_loads_[e];
    Real work = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto p = static_cast<std::size_t>(tri_[e][i]);
        const Vec3 dx = s.x[p] - s.x_prev[p];
        for (std::size_t c = 0; c < 3; ++c)
            work += loads[6 * i + c] * dx(static_cast<Eigen::Index>(c)) +
                    loads[6 * i + 3 + c] * s.dtheta[p](static_cast<Eigen::Index>(c));
    }
    t.strain_work += 0.5 * work;
    t.eroded_work += 0.5 * work;
    eroded_[e] = k_eroded;
}

void ShellElements::check_erosion(std::size_t e, Real work, ElementTotals& t,
                                  const std::array<Real, 18>& loads) {
    const ElementErosion& rule = erosion_[static_cast<std::size_t>(section_[e])];
    if (!rule.active()) return;
    element_work_[e] += work;
    const ElementGroup& group = group_of(e);
    const GroupPlace place = place_of(e);
    if (!rule.erodes([&](std::size_t p) { return group.plastic_strain(place, p); })) return;
    eroded_[e] = k_eroded_pending;  // from the next step on (this step's loads stand)
    last_loads_[e] = loads;
    ++t.eroded;
    t.eroded_work += element_work_[e];
}

}  // namespace fpmshell
