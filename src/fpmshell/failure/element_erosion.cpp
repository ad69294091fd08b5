#include "fpmshell/failure/element_erosion.hpp"

namespace fpmshell {

ElementErosion::ElementErosion(const MaterialFailure& failure, int n_inplane, int n_through)
    : active_(failure.active()),
      plastic_strain_{failure.plastic_strain},
      points_(failure.points),
      n_inplane_(n_inplane),
      n_through_(n_through) {}

}  // namespace fpmshell
