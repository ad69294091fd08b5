// Structured triangle meshes of the benchmark shells (model-format.md `mesh: {generator: ...}`).
// Every generator returns counter-clockwise triangles about the documented normal and names its
// edges as node sets (the model reader adds the set `all`). Parameters are validated by the
// model reader, which knows the file lines; the generators throw std::invalid_argument when a
// precondition below is violated anyway.
#pragma once

#include "fpmshell/core/types.hpp"
#include "fpmshell/mesh/mesh_data.hpp"

namespace fpmshell {

/// How each quadrilateral cell of a structured grid is cut into triangles. Cell corners a, b,
/// c, d are counter-clockwise, a = (i, j), b = (i+1, j), c = (i+1, j+1), d = (i, j+1).
enum class DiagonalPattern {
    Right,      ///< diagonal a-c: triangles (a, b, c), (a, c, d)
    Left,       ///< diagonal b-d: triangles (a, b, d), (b, c, d)
    Alternate,  ///< Right when i + j is even, Left otherwise (checkerboard)
    Cross       ///< a centre node e per cell, 4 triangles (a,b,e) (b,c,e) (c,d,e) (d,a,e)
};

/// Flat rectangle [origin.x, origin.x + length_x] x [origin.y, origin.y + length_y] in the
/// plane z = origin.z, normal +z. Corner nodes are numbered i + j (nx + 1) (i along x), then the
/// centre nodes of the cross pattern. Node sets: xmin, xmax, ymin, ymax, boundary.
/// Preconditions: lengths > 0, nx, ny >= 1.
struct PlateParams {
    Real length_x = 1;
    Real length_y = 1;
    Index nx = 1;
    Index ny = 1;
    Vec3 origin = Vec3::Zero();
    DiagonalPattern pattern = DiagonalPattern::Right;
};
[[nodiscard]] MeshData generate_plate(const PlateParams& p);

/// Circular cylinder panel, axis along y from y = 0 to y = length. The point at angle phi
/// (measured from +z towards +x) is (R sin phi, y, R cos phi); phi runs from angle_start_deg to
/// angle_start_deg + angle_deg. Normal: outwards, away from the axis.
/// Node sets: y0, y1 (the curved ends), arc0 (phi = start), arc1 (phi = start + angle),
/// boundary (union). With angle_deg = 360 the seam is merged (closed tube): no arc0/arc1.
/// Preconditions: radius, length > 0, 0 < angle_deg <= 360, divisions >= 1 (>= 3 closed).
struct CylinderPanelParams {
    Real radius = 1;
    Real length = 1;
    Real angle_deg = 90;
    Real angle_start_deg = -45;
    Index divisions_arc = 1;
    Index divisions_length = 1;
    DiagonalPattern pattern = DiagonalPattern::Right;
};
[[nodiscard]] MeshData generate_cylinder_panel(const CylinderPanelParams& p);

/// Number of segments of ring k (1..n) of a spherical cap with this sector, or 0 when the
/// sector has no ring pattern: a multiple of 60 degrees gives k sector/60 segments (the
/// hexagonal pattern: a full cap of n rings has 1 + 3 n (n + 1) nodes); otherwise a multiple of
/// 90 degrees gives 2 k sector/90 segments (8 k per full turn).
[[nodiscard]] Index spherical_cap_ring_segments(Real sector_deg, Index k);

/// Spherical cap of a sphere centred at the origin, apex (0, 0, R), normal outwards. Ring k
/// (k = 1..divisions) lies at polar angle k half_angle / divisions; azimuth runs from +x towards
/// +y over [0, sector_deg]. Consecutive rings are joined by walking both in azimuth, always
/// advancing the ring whose next node has the smaller azimuth (the inner one on a tie).
/// Node 0 is the apex, then ring by ring in azimuth order. Node sets: apex (1 node), rim, and
/// when sector_deg < 360: edge0 (azimuth 0) and edge1 (azimuth sector), both with the apex.
/// Preconditions: radius > 0, 0 < half_angle_deg < 180, sector as above, divisions >= 1.
struct SphericalCapParams {
    Real radius = 1;
    Real half_angle_deg = 30;
    Real sector_deg = 360;
    Index divisions = 1;
};
[[nodiscard]] MeshData generate_spherical_cap(const SphericalCapParams& p);

/// Flat annulus in the plane z = 0, normal +z, radius from inner_radius to outer_radius and
/// azimuth from 0 (the +x axis) towards +y over sector_deg. The ring is never closed: with
/// sector_deg = 360 the nodes at azimuth 0 and 360 are distinct (a slit) at the same position.
/// Node sets: inner, outer, edge0 (azimuth 0), edge1 (azimuth sector).
/// Preconditions: 0 < inner_radius < outer_radius, 0 < sector_deg <= 360, divisions >= 1.
struct AnnulusParams {
    Real inner_radius = 0.5;
    Real outer_radius = 1;
    Index divisions_radial = 1;
    Index divisions_angle = 1;
    Real sector_deg = 360;
    DiagonalPattern pattern = DiagonalPattern::Right;
};
[[nodiscard]] MeshData generate_annulus(const AnnulusParams& p);

/// Thin-walled square tube, axis along z from z = 0 to z = length, mid-surface walls at
/// x = +-width/2 and y = +-width/2, normal outwards. sector_deg = 360: the whole tube (the
/// perimeter starts at (width/2, -width/2) and runs counter-clockwise seen from +z);
/// sector_deg = 90: the quarter x >= 0, y >= 0 (half of the wall x = width/2 from y = 0, then
/// half of the wall y = width/2 to x = 0), for a model with two symmetry planes.
/// divisions_width: divisions across each modelled face (a half wall in the quarter model).
/// Node sets: bottom (z = 0), top (z = length), corners (the corner lines); quarter model also
/// x0 (on the plane x = 0) and y0 (on the plane y = 0).
/// Preconditions: width, length > 0; sector 90 or 360; divisions >= 1.
struct SquareTubeParams {
    Real width = 1;
    Real length = 1;
    Real sector_deg = 360;
    Index divisions_width = 1;
    Index divisions_length = 1;
    DiagonalPattern pattern = DiagonalPattern::Right;
};
[[nodiscard]] MeshData generate_square_tube(const SquareTubeParams& p);

/// Node and triangle counts a generator will produce (computed in floating point, so that the
/// model reader can refuse absurd sizes before allocating anything).
struct MeshSize {
    double nodes = 0;
    double triangles = 0;
};
[[nodiscard]] MeshSize grid_mesh_size(double ni, double nj, DiagonalPattern pattern,
                                      bool periodic_i);
[[nodiscard]] MeshSize spherical_cap_mesh_size(const SphericalCapParams& p);

}  // namespace fpmshell
