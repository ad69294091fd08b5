// Mass properties of the solid inside a closed surface (see enclosed_solid.hpp).
#include "fpmshell/model/enclosed_solid.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace fpmshell {

std::optional<std::string> open_surface_edge(const std::vector<std::array<Index, 3>>& faces) {
    // per undirected edge (low, high): the faces running low -> high and high -> low
    std::map<std::pair<Index, Index>, std::array<int, 2>> edges;
    for (const auto& f : faces)
        for (int k = 0; k < 3; ++k) {
            const Index a = f[static_cast<std::size_t>(k)];
            const Index b = f[static_cast<std::size_t>((k + 1) % 3)];
            auto& count = edges[{std::min(a, b), std::max(a, b)}];
            ++count[a < b ? 0 : 1];
        }
    for (const auto& [edge, count] : edges)
        if (count[0] != 1 || count[1] != 1)
            return "the edge between particles " + std::to_string(edge.first + 1) + " and " +
                   std::to_string(edge.second + 1) + " is on " +
                   std::to_string(count[0] + count[1]) +
                   (count[0] + count[1] == 2 ? " faces that run the same way"
                                             : " faces (a closed surface has it on two)");
    return std::nullopt;
}

RigidInertia enclosed_solid_inertia(const std::vector<std::array<Index, 3>>& faces,
                                    const std::vector<Vec3>& nodes, Real density) {
    // the reference point: the mean of the corners (rounding small against the body's size)
    Vec3 origin = Vec3::Zero();
    for (const auto& f : faces)
        for (const Index p : f) origin += nodes[static_cast<std::size_t>(p)];
    if (!faces.empty()) origin /= static_cast<Real>(3 * faces.size());
    // eq. 6.11-8: tetrahedron (0, a, b, c): V = a.(b x c)/6, first moment V (a+b+c)/4, second
    // moment V/20 (a a^T + b b^T + c c^T + s s^T), s = a+b+c
    Real volume = 0;
    Vec3 first = Vec3::Zero();
    Mat3 second = Mat3::Zero();
    for (const auto& f : faces) {
        const Vec3 a = nodes[static_cast<std::size_t>(f[0])] - origin;
        const Vec3 b = nodes[static_cast<std::size_t>(f[1])] - origin;
        const Vec3 c = nodes[static_cast<std::size_t>(f[2])] - origin;
        const Real v = a.dot(b.cross(c)) / 6.0;
        const Vec3 s = a + b + c;
        volume += v;
        first += (v / 4.0) * s;
        second += (v / 20.0) *
                  (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
    RigidInertia out;
    if (!(std::abs(volume) > 0)) return out;
    const Vec3 centre = first / volume;  // the signs cancel
    // about the centre: S_c = S_o - V c c^T; J = tr(S) I - S, times the density
    const Mat3 about_centre = second - volume * centre * centre.transpose();
    const Real sign = volume > 0 ? 1.0 : -1.0;
    out.mass = density * std::abs(volume);
    out.centre = origin + centre;
    out.tensor = sign * density * (about_centre.trace() * Mat3::Identity() - about_centre);
    return out;
}

}  // namespace fpmshell
