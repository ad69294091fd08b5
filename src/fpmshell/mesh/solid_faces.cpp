// Outer faces of parts meshed with solids (see solid_faces.hpp).
#include "fpmshell/mesh/solid_faces.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace fpmshell {
namespace {

/// The faces of a solid by its nodes: the 4 faces of a tetrahedron (4 distinct nodes; a
/// hexahedron's faces would fold it), else the 6 faces of the hexahedron with repeated nodes
/// dropped (a pentahedron's N5 = N6, N7 = N8 leave 3 quadrangles and 2 triangles).
std::vector<std::vector<long long>> solid_faces(const std::array<long long, 8>& n) {
    std::set<long long> distinct(n.begin(), n.end());
    if (distinct.size() == 4 && n[4] == n[3] && n[5] == n[3] && n[6] == n[3] && n[7] == n[3])
        return {{n[0], n[2], n[1]}, {n[0], n[1], n[3]}, {n[1], n[2], n[3]}, {n[2], n[0], n[3]}};
    static constexpr int k_hex_faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                              {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    std::vector<std::vector<long long>> out;
    for (const auto& f : k_hex_faces) {
        std::vector<long long> face;
        for (const int k : f)
            if (face.empty() || face.back() != n[static_cast<std::size_t>(k)])
                face.push_back(n[static_cast<std::size_t>(k)]);
        while (face.size() > 1 && face.front() == face.back()) face.pop_back();
        std::set<long long> unique(face.begin(), face.end());
        if (unique.size() == face.size() && face.size() >= 3) out.push_back(face);
    }
    return out;
}

}  // namespace

std::vector<SolidFace> outer_solid_faces(const std::vector<SolidElement>& solids,
                                         const std::unordered_map<long long, Vec3>& nodes) {
    const auto at = [&](long long id) {
        const auto it = nodes.find(id);
        return it == nodes.end() ? Vec3(Vec3::Zero()) : it->second;
    };
    std::vector<SolidFace> faces;
    std::map<std::pair<long long, std::vector<long long>>, std::size_t> seen;  // part, sorted
    std::vector<std::uint8_t> shared;
    for (const SolidElement& s : solids) {
        Vec3 centre = Vec3::Zero();
        for (const long long id : s.nodes) centre += at(id);
        centre /= 8.0;
        for (std::vector<long long>& face : solid_faces(s.nodes)) {
            std::vector<long long> key = face;
            std::sort(key.begin(), key.end());
            const auto [it, fresh] = seen.try_emplace({s.part, key}, faces.size());
            if (!fresh) {  // a second solid has it: inside the part
                shared[it->second] = 1;
                continue;
            }
            // outward: the normal (the diagonals' cross product for a quadrangle) away from
            // the solid's centre
            Vec3 middle = Vec3::Zero();
            for (const long long id : face) middle += at(id);
            middle /= static_cast<Real>(face.size());
            const Vec3 normal =
                face.size() == 3
                    ? Vec3((at(face[1]) - at(face[0])).cross(at(face[2]) - at(face[0])))
                    : Vec3((at(face[2]) - at(face[0])).cross(at(face[3]) - at(face[1])));
            if (normal.dot(middle - centre) < 0) std::reverse(face.begin(), face.end());
            faces.push_back({s.part, s.id, std::move(face)});
            shared.push_back(0);
        }
    }
    std::vector<SolidFace> outer;
    for (std::size_t k = 0; k < faces.size(); ++k)
        if (!shared[k]) outer.push_back(std::move(faces[k]));
    return outer;
}

}  // namespace fpmshell
