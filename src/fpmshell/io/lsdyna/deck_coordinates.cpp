// Local coordinate systems of a deck (*DEFINE_COORDINATE_SYSTEM, _VECTOR, _NODES) and the
// directions given in them (the ICID of the initial velocities): each system is its three unit
// axes in global components, the columns of the rotation from local to global.
#include <cmath>

#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {
namespace {

std::array<Real, 3> cross(const std::array<Real, 3>& a, const std::array<Real, 3>& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

/// *DEFINE_COORDINATE_SYSTEM: CID, the origin O, a point L on the local x axis (CIDL 0), then a
/// point P in the local x-y plane; _VECTOR: CID, the x axis X, a vector V in the x-y plane
/// (its NID only makes the system turn with a node later, which the velocities of t = 0 do not
/// see); _NODES: three nodes, whose positions the translator does not know (refused where used).
/// x = unit(L - O) or unit(X), z = unit(x cross (P - O) or x cross V), y = z cross x.
void DeckTranslator::define_coordinate(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    const std::size_t first = opt.count("TITLE") ? 1 : 0;
    const bool system = opt.count("SYSTEM") != 0, vector = opt.count("VECTOR") != 0;
    const bool nodes = opt.count("NODES") != 0;
    for (const std::string& o : opt)
        if (o != "TITLE" && o != "SYSTEM" && o != "VECTOR" && o != "NODES")
            refuse(b, "*DEFINE_COORDINATE_" + o + " is not supported");
    if (!system && !vector && !nodes) refuse(b, unsupported_reason(b.keyword));
    const Card f = required_card(b, first, "CID and the system's points or vectors");
    const long long cid = f.id(0, "CID");
    CoordinateSystemDef def{{&b, f.line()}, {}, nodes};
    if (!nodes) {
        std::array<Real, 3> x{}, in_plane{};
        if (system) {
            const Card g = required_card(b, first + 1, "XP, YP, ZP");
            if (f.id(7, "CIDL") != 0)
                f.fail("CIDL: a system given in another local system is not supported");
            for (std::size_t k = 0; k < 3; ++k) {
                const Real o = f.real(1 + k, "XO, YO, ZO");
                x[k] = f.real(4 + k, "XL, YL, ZL") - o;
                in_plane[k] = g.real(k, "XP, YP, ZP") - o;
            }
        } else {
            for (std::size_t k = 0; k < 3; ++k) {
                x[k] = f.real(1 + k, "XX, YX, ZX");
                in_plane[k] = f.real(4 + k, "XV, YV, ZV");
            }
        }
        const std::array<Real, 3> normal = cross(x, in_plane);
        if (std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]) <=
            1e-12 * (std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) *
                     std::sqrt(in_plane[0] * in_plane[0] + in_plane[1] * in_plane[1] +
                               in_plane[2] * in_plane[2])))
            f.fail("the x axis and the point or vector in the x-y plane must not be parallel");
        const std::array<Real, 3> ex = unit(x), ez = unit(normal), ey = cross(ez, ex);
        def.axes = {ex, ey, ez};
    }
    if (const auto other = coordinate_systems_.find(cid); other != coordinate_systems_.end())
        f.fail("coordinate system " + std::to_string(cid) + " is defined twice (first at " +
               place(other->second.at) + ")");
    coordinate_systems_[cid] = def;
}

std::array<Real, 3> DeckTranslator::to_global(const Card& f, long long cid,
                                              const std::array<Real, 3>& local) const {
    if (cid == 0) return local;
    const auto it = coordinate_systems_.find(cid);
    if (it == coordinate_systems_.end())
        f.fail("ICID " + std::to_string(cid) +
               ": no *DEFINE_COORDINATE_SYSTEM or _VECTOR "
               "defines it");
    if (it->second.from_nodes)
        f.fail("ICID " + std::to_string(cid) +
               ": a system of *DEFINE_COORDINATE_NODES (axes from node positions) is not "
               "supported here; give it as *DEFINE_COORDINATE_SYSTEM or _VECTOR");
    const auto& a = it->second.axes;
    std::array<Real, 3> g{};
    for (std::size_t r = 0; r < 3; ++r)
        g[r] = a[0][r] * local[0] + a[1][r] * local[1] + a[2][r] * local[2];
    return g;
}

}  // namespace fpmshell::deck
