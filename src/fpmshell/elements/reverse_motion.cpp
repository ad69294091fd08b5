#include "fpmshell/elements/reverse_motion.hpp"

namespace fpmshell {

ReversedTriangle reverse_motion(const std::array<Vec3, 3>& base, const std::array<Vec3, 3>& current,
                                const std::array<Vec3, 3>& dtheta,
                                const std::array<Vec3, 3>& drill_axis) {
    TriangleMotion<Real> m;
    for (std::size_t i = 0; i < 3; ++i) {
        m.base[i] = to_v3(base[i]);
        m.current[i] = to_v3(current[i]);
        m.dtheta[i] = to_v3(dtheta[i]);
        m.drill_axis[i] = to_v3(drill_axis[i]);
    }
    ReversedTriangle out;
    (void)path_element<ExactRotations>(m, out.local, out.checks);
    return out;
}

}  // namespace fpmshell
