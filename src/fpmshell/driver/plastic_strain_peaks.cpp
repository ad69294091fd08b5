// The plastic strain peaks of summary.json; described in plastic_strain_peaks.hpp.
#include "fpmshell/driver/plastic_strain_peaks.hpp"

#include <limits>

#include "fpmshell/core/communicator.hpp"
#include "fpmshell/driver/output_fields.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

int PlasticStrainPeaks::surface() const {
    int best = -1;
    for (int s = 0; s < 3; ++s)
        if (peak[static_cast<std::size_t>(s)] >
            (best < 0 ? 0.0 : peak[static_cast<std::size_t>(best)]))
            best = s;
    return best;
}

PlasticStrainPeaks plastic_strain_peaks(const ExplicitSolver& solver) {
    constexpr ShellSurface k_surfaces[] = {ShellSurface::Bottom, ShellSurface::Middle,
                                           ShellSurface::Top};
    PlasticStrainPeaks peaks;
    const std::vector<Index> elements = solver.elements().computed_elements();
    for (std::size_t s = 0; s < 3; ++s) {
        Real& peak = peaks.peak[s];
        Index& at = peaks.element[s];
        for (const Index e : elements) {  // not in element order on several ranks
            const Real v = surface_plastic_strain(solver.elements(), e, k_surfaces[s]);
            if (v > peak || (v == peak && v > 0 && e < at)) {
                peak = v;
                at = e;
            }
        }
        const Communicator& comm = Communicator::world();
        if (comm.distributed()) {
            // the largest peak, and among the ranks that reach it the lowest element
            const Index none = std::numeric_limits<Index>::max();
            const auto [negative, e] = comm.min_loc(-peak, at >= 0 ? at : none);
            peak = -negative;
            at = peak > 0 ? e : -1;
        }
    }
    return peaks;
}

}  // namespace fpmshell
