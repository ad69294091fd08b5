#include "fpmshell/solver/edge_opening.hpp"

#include <algorithm>

namespace fpmshell {
namespace {

ElementPair ordered(Index e, Index f) { return e < f ? ElementPair{e, f} : ElementPair{f, e}; }

}  // namespace

bool EdgeOpening::is_open(Index e, Index f) const {
    return std::binary_search(open_.begin(), open_.end(), ordered(e, f));
}

void EdgeOpening::add(const std::vector<ElementPair>& sides) {
    for (const ElementPair& s : sides) {
        if (is_open(s.first, s.second)) continue;
        open_.insert(std::upper_bound(open_.begin(), open_.end(), ordered(s.first, s.second)),
                     ordered(s.first, s.second));
        ++open_count_[static_cast<std::size_t>(s.first)];
        ++open_count_[static_cast<std::size_t>(s.second)];
    }
}

std::vector<ElementPair> EdgeOpening::open_chosen(const Mesh& mesh, std::vector<Real> choices) {
    struct Chosen {
        Real traction;
        ElementPair side;
    };
    std::vector<Chosen> order;
    for (std::size_t i = 0; i + 2 < choices.size(); i += 3)
        order.push_back({choices[i + 2], ordered(static_cast<Index>(choices[i]),
                                                 static_cast<Index>(choices[i + 1]))});
    std::sort(order.begin(), order.end(), [](const Chosen& a, const Chosen& b) {
        return a.traction != b.traction ? a.traction > b.traction : a.side < b.side;
    });
    std::vector<ElementPair> opened;
    for (const Chosen& c : order) {
        if (is_open(c.side.first, c.side.second)) continue;
        if (!may_open(mesh, c.side.first) || !may_open(mesh, c.side.second)) continue;
        add({c.side});
        opened.push_back(c.side);
    }
    return opened;
}

bool EdgeOpening::may_open(const Mesh& mesh, Index e) const {
    // two open sides at most (a triangle's two sides always meet at a corner: the crack turns
    // through it), and a closed one kept
    return open_sides_of(e) < 2 && closed_sides(mesh, e) >= 2;
}

int EdgeOpening::closed_sides(const Mesh& mesh, Index e) const {
    int closed = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const Index across = mesh.topology.side_neighbour[3 * static_cast<std::size_t>(e) + i];
        if (across >= 0 && !is_open(e, across)) ++closed;
    }
    return closed;
}

bool EdgeOpening::on_free_side(const Mesh& mesh, Index p) const {
    for (const Index f : mesh.topology.elements_of(p)) {
        const auto& t = mesh.triangles[static_cast<std::size_t>(f)];
        for (int i = 0; i < 3; ++i) {
            if (t[static_cast<std::size_t>(i)] == p) continue;  // side i is opposite corner i
            const Index across =
                mesh.topology
                    .side_neighbour[3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(i)];
            if (across < 0 || is_open(f, across)) return true;
        }
    }
    return false;
}

// eq. 7.7-1: among the candidate sides, the largest normal membrane force n . N n across the
// side (> 0), the first side in corner order among equals.
EdgeOpening::Choice EdgeOpening::side_to_open(const Mesh& mesh, Index e, const Voigt3& n) const {
    const auto ue = static_cast<std::size_t>(e);
    Choice best;
    const auto& t = mesh.triangles[ue];
    const Vec3& p0 = mesh.x[static_cast<std::size_t>(t[0])];
    const Vec3 ex = (mesh.x[static_cast<std::size_t>(t[1])] - p0).normalized();
    const Vec3 normal = ex.cross(mesh.x[static_cast<std::size_t>(t[2])] - p0);
    const Vec3 ey = normal.normalized().cross(ex);
    for (std::size_t i = 0; i < 3; ++i) {
        const Index across = mesh.topology.side_neighbour[3 * ue + i];
        if (across < 0 || is_open(e, across)) continue;
        const Index a = t[(i + 1) % 3], b = t[(i + 2) % 3];
        if (!may_open(mesh, e) || !may_open(mesh, across)) continue;
        if (mesh.pinned[static_cast<std::size_t>(a)] || mesh.pinned[static_cast<std::size_t>(b)])
            continue;
        if (!mesh.failed(across) && !on_free_side(mesh, a) && !on_free_side(mesh, b)) continue;
        const Vec3 side = mesh.x[static_cast<std::size_t>(b)] - mesh.x[static_cast<std::size_t>(a)];
        const Real sx = side.dot(ex), sy = side.dot(ey), length2 = sx * sx + sy * sy;
        if (!(length2 > 0)) continue;
        // the side's in-plane normal (-sy, sx) / |s|: n . N n
        const Real traction = (n[0] * sy * sy + n[1] * sx * sx - 2.0 * n[2] * sx * sy) / length2;
        if (traction > best.traction) best = {across, traction};
    }
    return best;
}

}  // namespace fpmshell
