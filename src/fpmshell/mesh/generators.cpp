// Structured triangle meshes (see generators.hpp). The plate, the cylinder panel and the annulus
// share one parametric grid: triangles counter-clockwise in the (u, v) parameter plane, then a
// map (u, v) -> x whose tangents satisfy x_u x x_v = (documented normal) keeps them
// counter-clockwise about that normal.
#include "fpmshell/mesh/generators.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fpmshell {
namespace {

constexpr Real k_pi = std::numbers::pi_v<Real>;

Real deg_to_rad(Real deg) { return deg * k_pi / 180.0; }

/// A grid of (ni + 1) x (nj + 1) corner nodes in index space (u = i, v = j), plus one centre
/// node per cell for the cross pattern. With periodic_i the column i = ni is the column i = 0.
struct ParamGrid {
    std::vector<Vec2> uv;  ///< parameter coordinates of every node, in cell units
    std::vector<std::array<Index, 3>> triangles;
    Index ni = 0;
    Index nj = 0;
    bool periodic_i = false;

    [[nodiscard]] Index corner(Index i, Index j) const {
        const Index columns = periodic_i ? ni : ni + 1;
        if (periodic_i) i %= ni;
        return j * columns + i;
    }
};

ParamGrid make_param_grid(Index ni, Index nj, DiagonalPattern pattern, bool periodic_i) {
    ParamGrid g;
    g.ni = ni;
    g.nj = nj;
    g.periodic_i = periodic_i;
    const Index columns = periodic_i ? ni : ni + 1;
    g.uv.reserve(static_cast<std::size_t>(columns) * static_cast<std::size_t>(nj + 1));
    for (Index j = 0; j <= nj; ++j)
        for (Index i = 0; i < columns; ++i)
            g.uv.emplace_back(static_cast<Real>(i), static_cast<Real>(j));
    const std::size_t per_cell = pattern == DiagonalPattern::Cross ? 4 : 2;
    g.triangles.reserve(static_cast<std::size_t>(ni) * static_cast<std::size_t>(nj) * per_cell);
    for (Index j = 0; j < nj; ++j) {
        for (Index i = 0; i < ni; ++i) {
            const Index a = g.corner(i, j);
            const Index b = g.corner(i + 1, j);
            const Index c = g.corner(i + 1, j + 1);
            const Index d = g.corner(i, j + 1);
            bool right = pattern == DiagonalPattern::Right;
            if (pattern == DiagonalPattern::Alternate) right = (i + j) % 2 == 0;
            if (pattern == DiagonalPattern::Cross) {
                const auto e = static_cast<Index>(g.uv.size());
                g.uv.emplace_back(static_cast<Real>(i) + 0.5, static_cast<Real>(j) + 0.5);
                g.triangles.push_back({a, b, e});
                g.triangles.push_back({b, c, e});
                g.triangles.push_back({c, d, e});
                g.triangles.push_back({d, a, e});
            } else if (right) {
                g.triangles.push_back({a, b, c});
                g.triangles.push_back({a, c, d});
            } else {
                g.triangles.push_back({a, b, d});
                g.triangles.push_back({b, c, d});
            }
        }
    }
    return g;
}

/// Corner nodes of the grid line i = const (j from 0 to nj), sorted.
std::vector<Index> column_nodes(const ParamGrid& g, Index i) {
    std::vector<Index> s;
    for (Index j = 0; j <= g.nj; ++j) s.push_back(g.corner(i, j));
    std::sort(s.begin(), s.end());
    return s;
}

/// Corner nodes of the grid line j = const, sorted and unique (periodic grids repeat i = 0).
std::vector<Index> row_nodes(const ParamGrid& g, Index j) {
    std::vector<Index> s;
    for (Index i = 0; i <= g.ni; ++i) s.push_back(g.corner(i, j));
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    return s;
}

std::vector<Index> set_union(std::initializer_list<const std::vector<Index>*> sets) {
    std::vector<Index> u;
    for (const auto* s : sets) u.insert(u.end(), s->begin(), s->end());
    std::sort(u.begin(), u.end());
    u.erase(std::unique(u.begin(), u.end()), u.end());
    return u;
}

MeshData map_grid(const ParamGrid& g, const std::function<Vec3(Real, Real)>& position) {
    MeshData m;
    m.nodes.reserve(g.uv.size());
    for (const Vec2& uv : g.uv) m.nodes.push_back(position(uv.x(), uv.y()));
    m.triangles = g.triangles;
    return m;
}

void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("mesh generator: " + what);
}

}  // namespace

MeshSize grid_mesh_size(double ni, double nj, DiagonalPattern pattern, bool periodic_i) {
    const double cells = ni * nj;
    const double corners = (periodic_i ? ni : ni + 1) * (nj + 1);
    if (pattern == DiagonalPattern::Cross) return {corners + cells, 4 * cells};
    return {corners, 2 * cells};
}

MeshData generate_plate(const PlateParams& p) {
    require(p.length_x > 0 && p.length_y > 0, "plate lengths must be positive");
    require(p.nx >= 1 && p.ny >= 1, "plate divisions must be at least 1");
    const ParamGrid g = make_param_grid(p.nx, p.ny, p.pattern, false);
    const Real hx = p.length_x / static_cast<Real>(p.nx);
    const Real hy = p.length_y / static_cast<Real>(p.ny);
    MeshData m = map_grid(g, [&](Real u, Real v) {
        return Vec3(p.origin.x() + u * hx, p.origin.y() + v * hy, p.origin.z());
    });
    // Put the far edges exactly on origin + length (u * hx may round differently).
    for (Index j = 0; j <= p.ny; ++j) m.nodes[g.corner(p.nx, j)].x() = p.origin.x() + p.length_x;
    for (Index i = 0; i <= p.nx; ++i) m.nodes[g.corner(i, p.ny)].y() = p.origin.y() + p.length_y;
    auto& s = m.node_sets;
    s["xmin"] = column_nodes(g, 0);
    s["xmax"] = column_nodes(g, p.nx);
    s["ymin"] = row_nodes(g, 0);
    s["ymax"] = row_nodes(g, p.ny);
    s["boundary"] = set_union({&s["xmin"], &s["xmax"], &s["ymin"], &s["ymax"]});
    return m;
}

MeshData generate_cylinder_panel(const CylinderPanelParams& p) {
    require(p.radius > 0 && p.length > 0, "cylinder radius and length must be positive");
    require(p.angle_deg > 0 && p.angle_deg <= 360, "cylinder angle must be in (0, 360]");
    const bool closed = p.angle_deg == 360;
    require(p.divisions_arc >= (closed ? 3 : 1) && p.divisions_length >= 1,
            "cylinder divisions too small");
    const ParamGrid g = make_param_grid(p.divisions_arc, p.divisions_length, p.pattern, closed);
    const Real dphi = deg_to_rad(p.angle_deg) / static_cast<Real>(p.divisions_arc);
    const Real phi0 = deg_to_rad(p.angle_start_deg);
    const Real dy = p.length / static_cast<Real>(p.divisions_length);
    // x_phi x x_y = (R sin phi, 0, R cos phi): counter-clockwise in (phi, y) is outwards.
    MeshData m = map_grid(g, [&](Real u, Real v) {
        const Real phi = phi0 + u * dphi;
        return Vec3(p.radius * std::sin(phi), v * dy, p.radius * std::cos(phi));
    });
    for (Index i = 0; i <= p.divisions_arc; ++i)
        m.nodes[g.corner(i, p.divisions_length)].y() = p.length;
    auto& s = m.node_sets;
    s["y0"] = row_nodes(g, 0);
    s["y1"] = row_nodes(g, p.divisions_length);
    if (closed) {
        s["boundary"] = set_union({&s["y0"], &s["y1"]});
    } else {
        s["arc0"] = column_nodes(g, 0);
        s["arc1"] = column_nodes(g, p.divisions_arc);
        s["boundary"] = set_union({&s["y0"], &s["y1"], &s["arc0"], &s["arc1"]});
    }
    return m;
}

MeshData generate_annulus(const AnnulusParams& p) {
    require(p.inner_radius > 0 && p.outer_radius > p.inner_radius,
            "annulus radii must satisfy 0 < inner < outer");
    require(p.sector_deg > 0 && p.sector_deg <= 360, "annulus sector must be in (0, 360]");
    require(p.divisions_radial >= 1 && p.divisions_angle >= 1, "annulus divisions too small");
    // u = radial index, v = angular index: x_r x x_theta = +z r, so counter-clockwise is +z.
    const ParamGrid g = make_param_grid(p.divisions_radial, p.divisions_angle, p.pattern, false);
    const Real dr = (p.outer_radius - p.inner_radius) / static_cast<Real>(p.divisions_radial);
    const Real dtheta = deg_to_rad(p.sector_deg) / static_cast<Real>(p.divisions_angle);
    MeshData m = map_grid(g, [&](Real u, Real v) {
        const Real r =
            u == static_cast<Real>(p.divisions_radial) ? p.outer_radius : p.inner_radius + u * dr;
        const Real theta = v * dtheta;
        return Vec3(r * std::cos(theta), r * std::sin(theta), 0.0);
    });
    auto& s = m.node_sets;
    s["inner"] = column_nodes(g, 0);
    s["outer"] = column_nodes(g, p.divisions_radial);
    s["edge0"] = row_nodes(g, 0);
    s["edge1"] = row_nodes(g, p.divisions_angle);
    return m;
}

MeshData generate_square_tube(const SquareTubeParams& p) {
    require(p.width > 0 && p.length > 0, "tube width and length must be positive");
    const bool quarter = std::abs(p.sector_deg - 90) < 1e-9;
    require(quarter || std::abs(p.sector_deg - 360) < 1e-9,
            "tube sector must be 90 or 360 degrees");
    require(p.divisions_width >= 1 && p.divisions_length >= 1, "tube divisions must be at least 1");
    const Index faces = quarter ? 2 : 4;
    const Index dw = p.divisions_width;
    const ParamGrid g = make_param_grid(faces * dw, p.divisions_length, p.pattern, !quarter);
    const Real half = 0.5 * p.width;
    const Real dz = p.length / static_cast<Real>(p.divisions_length);
    // Position along the perimeter: face k = floor(u / dw), fraction t along it. Tangents
    // x_u x x_z point outwards on every face, so counter-clockwise in (u, z) is outwards.
    auto perimeter = [&](Real u) -> Vec2 {
        const Index k =
            std::min<Index>(static_cast<Index>(std::floor(u / static_cast<Real>(dw))), faces - 1);
        const Real t = (u - static_cast<Real>(k * dw)) / static_cast<Real>(dw);
        if (quarter)  // face 0: x = half, y 0 -> half; face 1: y = half, x half -> 0
            return k == 0 ? Vec2(half, t * half) : Vec2(half - t * half, half);
        const Real a = -half + t * p.width;
        switch (k) {
            case 0:
                return {half, a};
            case 1:
                return {-a, half};
            case 2:
                return {-half, -a};
            default:
                return {a, -half};
        }
    };
    MeshData m = map_grid(g, [&](Real u, Real v) {
        const Vec2 xy = perimeter(u);
        const Real z = v == static_cast<Real>(p.divisions_length) ? p.length : v * dz;
        return Vec3(xy.x(), xy.y(), z);
    });
    auto& s = m.node_sets;
    s["bottom"] = row_nodes(g, 0);
    s["top"] = row_nodes(g, p.divisions_length);
    std::vector<Index> corners;
    for (Index k = quarter ? 1 : 0; k < faces; ++k) {
        const auto c = column_nodes(g, k * dw);
        corners.insert(corners.end(), c.begin(), c.end());
    }
    std::sort(corners.begin(), corners.end());
    s["corners"] = corners;
    if (quarter) {
        s["y0"] = column_nodes(g, 0);
        s["x0"] = column_nodes(g, 2 * dw);
        for (Index n : s["x0"])
            m.nodes[static_cast<std::size_t>(n)].x() = 0;  // exactly on the plane
    }
    return m;
}

Index spherical_cap_ring_segments(Real sector_deg, Index k) {
    if (!(sector_deg > 0 && sector_deg <= 360)) return 0;
    const Real sixty = sector_deg / 60.0;
    if (std::abs(sixty - std::round(sixty)) < 1e-9)
        return k * static_cast<Index>(std::round(sixty));
    const Real ninety = sector_deg / 90.0;
    if (std::abs(ninety - std::round(ninety)) < 1e-9)
        return 2 * k * static_cast<Index>(std::round(ninety));
    return 0;
}

MeshSize spherical_cap_mesh_size(const SphericalCapParams& p) {
    const double c = spherical_cap_ring_segments(p.sector_deg, 1);
    const double n = p.divisions;
    const bool closed = std::abs(p.sector_deg - 360) < 1e-9;
    const double ring_nodes = c * n * (n + 1) / 2 + (closed ? 0.0 : n);
    return {1 + ring_nodes, c * n * n};
}

MeshData generate_spherical_cap(const SphericalCapParams& p) {
    require(p.radius > 0, "cap radius must be positive");
    require(p.half_angle_deg > 0 && p.half_angle_deg < 180, "cap half angle must be in (0, 180)");
    require(p.divisions >= 1, "cap divisions must be at least 1");
    require(spherical_cap_ring_segments(p.sector_deg, 1) > 0,
            "cap sector must be a multiple of 60 or 90 degrees up to 360");
    const bool closed = std::abs(p.sector_deg - 360) < 1e-9;
    const Real sector = deg_to_rad(p.sector_deg);
    const Real alpha = deg_to_rad(p.half_angle_deg);
    const Index n = p.divisions;

    MeshData m;
    m.nodes.emplace_back(0.0, 0.0, p.radius);
    // first[k]: index of the first node of ring k; ring 0 is the apex.
    std::vector<Index> first(static_cast<std::size_t>(n) + 1, 0);
    std::vector<Index> segments(static_cast<std::size_t>(n) + 1, 0);
    for (Index k = 1; k <= n; ++k) {
        const auto ku = static_cast<std::size_t>(k);
        segments[ku] = spherical_cap_ring_segments(p.sector_deg, k);
        first[ku] = static_cast<Index>(m.nodes.size());
        const Real theta = alpha * static_cast<Real>(k) / static_cast<Real>(n);
        const Index count = closed ? segments[ku] : segments[ku] + 1;
        for (Index q = 0; q < count; ++q) {
            const Real phi = sector * static_cast<Real>(q) / static_cast<Real>(segments[ku]);
            m.nodes.emplace_back(p.radius * std::sin(theta) * std::cos(phi),
                                 p.radius * std::sin(theta) * std::sin(phi),
                                 p.radius * std::cos(theta));
        }
    }
    // Node q (0..segments, q = segments is azimuth `sector`) of ring k.
    auto ring_node = [&](Index k, Index q) -> Index {
        const auto ku = static_cast<std::size_t>(k);
        if (k == 0) return 0;
        if (closed && q == segments[ku]) q = 0;
        return first[ku] + q;
    };
    // Join ring k-1 (inner, m_in segments) and ring k (outer): both walks start at azimuth 0;
    // the azimuths (p+1)/m_in and (q+1)/m_out are compared exactly in integers. With
    // x_theta x x_phi pointing outwards, both triangle kinds below are counter-clockwise in
    // (theta, phi), hence outward.
    for (Index k = 1; k <= n; ++k) {
        const Index m_in = segments[static_cast<std::size_t>(k - 1)];
        const Index m_out = segments[static_cast<std::size_t>(k)];
        Index pi = 0;
        Index qo = 0;
        while (pi < m_in || qo < m_out) {
            bool advance_outer = false;
            if (pi == m_in) {
                advance_outer = true;
            } else if (qo < m_out) {
                const auto lhs = static_cast<long long>(qo + 1) * m_in;   // outer next * m_in
                const auto rhs = static_cast<long long>(pi + 1) * m_out;  // inner next * m_out
                advance_outer = lhs < rhs;
            }
            if (advance_outer) {
                m.triangles.push_back(
                    {ring_node(k - 1, pi), ring_node(k, qo), ring_node(k, qo + 1)});
                ++qo;
            } else {
                m.triangles.push_back(
                    {ring_node(k - 1, pi), ring_node(k, qo), ring_node(k - 1, pi + 1)});
                ++pi;
            }
        }
    }
    auto& s = m.node_sets;
    s["apex"] = {0};
    std::vector<Index> rim;
    for (Index q = 0; q < (closed ? segments.back() : segments.back() + 1); ++q)
        rim.push_back(ring_node(n, q));
    s["rim"] = rim;
    if (!closed) {
        std::vector<Index> e0{0};
        std::vector<Index> e1{0};
        for (Index k = 1; k <= n; ++k) {
            e0.push_back(ring_node(k, 0));
            e1.push_back(ring_node(k, segments[static_cast<std::size_t>(k)]));
        }
        s["edge0"] = e0;
        s["edge1"] = e1;
    }
    return m;
}

}  // namespace fpmshell
