// The `mesh` block (see mesh_input.hpp).
#include "fpmshell/io/mesh_input.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/mesh/abaqus_reader.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/mesh/gmsh_reader.hpp"
#include "fpmshell/mesh/lsdyna_reader.hpp"

namespace fpmshell {
namespace {

constexpr long long k_max_divisions = 10'000'000;

const std::vector<std::string> k_generators = {"plate", "cylinder_panel", "spherical_cap",
                                               "annulus", "square_tube"};

DiagonalPattern read_pattern(const YamlMap& m) {
    const std::string p = m.choice_or("pattern", {"right", "left", "alternate", "cross"}, "right");
    if (p == "left") return DiagonalPattern::Left;
    if (p == "alternate") return DiagonalPattern::Alternate;
    if (p == "cross") return DiagonalPattern::Cross;
    return DiagonalPattern::Right;
}

Index divisions(const YamlMap& m, const std::string& key, long long min = 1) {
    return static_cast<Index>(m.at(key, "a whole number of divisions >= " + std::to_string(min))
                                  .integer(min, k_max_divisions));
}

Real positive(const YamlMap& m, const std::string& key) {
    return m.at(key, "a number > 0").positive();
}

/// An angle in degrees in (0, max] (or (0, max) when max is excluded).
Real angle(const YamlValue& v, Real max, bool max_included) {
    const Real a = v.real();
    if (!(a > 0) || a > max || (!max_included && a == max))
        v.fail("expected an angle in degrees greater than 0 and " +
               std::string(max_included ? "at most " : "less than ") +
               std::to_string(static_cast<int>(max)) + ", got " + v.describe());
    return a;
}

void check_size(const YamlValue& mesh, MeshSize size) {
    if (size.triangles > k_max_mesh_elements || size.nodes > k_max_mesh_elements)
        mesh.fail(
            "these divisions would make " + std::to_string(static_cast<long long>(size.triangles)) +
            " elements, more than the limit of " +
            std::to_string(static_cast<long long>(k_max_mesh_elements)) + "; reduce the divisions");
}

MeshData plate(const YamlValue& mesh) {
    const YamlMap m =
        mesh.map({"generator", "length_x", "length_y", "nx", "ny", "origin", "pattern"});
    PlateParams p;
    p.length_x = positive(m, "length_x");
    p.length_y = positive(m, "length_y");
    p.nx = divisions(m, "nx");
    p.ny = divisions(m, "ny");
    if (const auto o = m.find("origin")) p.origin = o->vec3();
    p.pattern = read_pattern(m);
    check_size(mesh, grid_mesh_size(p.nx, p.ny, p.pattern, false));
    return generate_plate(p);
}

MeshData cylinder_panel(const YamlValue& mesh) {
    const YamlMap m = mesh.map({"generator", "radius", "length", "angle_deg", "angle_start_deg",
                                "divisions_arc", "divisions_length", "pattern"});
    CylinderPanelParams p;
    p.radius = positive(m, "radius");
    p.length = positive(m, "length");
    p.angle_deg = angle(m.at("angle_deg", "the arc angle in degrees"), 360, true);
    const bool closed = std::abs(p.angle_deg - 360) < 1e-9;
    if (closed) p.angle_deg = 360;
    p.angle_start_deg = m.real_or("angle_start_deg", -p.angle_deg / 2);
    p.divisions_arc = divisions(m, "divisions_arc", closed ? 3 : 1);
    p.divisions_length = divisions(m, "divisions_length");
    p.pattern = read_pattern(m);
    check_size(mesh, grid_mesh_size(p.divisions_arc, p.divisions_length, p.pattern, closed));
    return generate_cylinder_panel(p);
}

MeshData spherical_cap(const YamlValue& mesh) {
    const YamlMap m =
        mesh.map({"generator", "radius", "half_angle_deg", "sector_deg", "divisions"});
    SphericalCapParams p;
    p.radius = positive(m, "radius");
    p.half_angle_deg =
        angle(m.at("half_angle_deg", "the half opening angle in degrees"), 180, false);
    if (const auto s = m.find("sector_deg")) {
        p.sector_deg = angle(*s, 360, true);
        if (spherical_cap_ring_segments(p.sector_deg, 1) == 0)
            s->fail(
                "the sector must be a multiple of 60 degrees (hexagonal ring pattern) or of "
                "90 degrees (8 k segments per turn on ring k), got " +
                s->describe());
        if (std::abs(p.sector_deg - 360) < 1e-9) p.sector_deg = 360;
    }
    p.divisions = divisions(m, "divisions");
    check_size(mesh, spherical_cap_mesh_size(p));
    return generate_spherical_cap(p);
}

MeshData annulus(const YamlValue& mesh) {
    const YamlMap m = mesh.map({"generator", "inner_radius", "outer_radius", "divisions_radial",
                                "divisions_angle", "sector_deg", "pattern"});
    AnnulusParams p;
    p.inner_radius = positive(m, "inner_radius");
    const YamlValue outer = m.at("outer_radius", "a number greater than inner_radius");
    p.outer_radius = outer.positive();
    if (!(p.outer_radius > p.inner_radius))
        outer.fail("must be greater than inner_radius (" + m.at("inner_radius").describe() +
                   "), got " + outer.describe());
    p.divisions_radial = divisions(m, "divisions_radial");
    p.divisions_angle = divisions(m, "divisions_angle");
    if (const auto s = m.find("sector_deg")) p.sector_deg = angle(*s, 360, true);
    p.pattern = read_pattern(m);
    check_size(mesh, grid_mesh_size(p.divisions_radial, p.divisions_angle, p.pattern, false));
    return generate_annulus(p);
}

MeshData square_tube(const YamlValue& mesh) {
    const YamlMap m = mesh.map({"generator", "width", "length", "sector_deg", "divisions_width",
                                "divisions_length", "pattern"});
    SquareTubeParams p;
    p.width = positive(m, "width");
    p.length = positive(m, "length");
    if (const auto s = m.find("sector_deg")) {
        p.sector_deg = s->real();
        if (!(std::abs(p.sector_deg - 90) < 1e-9 || std::abs(p.sector_deg - 360) < 1e-9))
            s->fail(
                "expected 90 (the quarter x >= 0, y >= 0, for two symmetry planes) or 360 (the "
                "whole tube), got " +
                s->describe());
    }
    p.divisions_width = divisions(m, "divisions_width");
    p.divisions_length = divisions(m, "divisions_length");
    p.pattern = read_pattern(m);
    const double faces = std::abs(p.sector_deg - 90) < 1e-9 ? 2 : 4;
    check_size(mesh,
               grid_mesh_size(faces * static_cast<double>(p.divisions_width),
                              static_cast<double>(p.divisions_length), p.pattern, faces == 4));
    return generate_square_tube(p);
}

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

MeshData from_file(const YamlValue& mesh, const std::string& base_dir) {
    const YamlMap m = mesh.map({"file"});
    const YamlValue file = m.at("file");
    const std::string name = file.name();
    std::filesystem::path path(name);
    if (path.is_relative() && !base_dir.empty()) path = std::filesystem::path(base_dir) / path;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        file.fail("the mesh file '" + path.string() + "' does not exist");
    if (!std::filesystem::is_regular_file(path, ec))
        file.fail("'" + path.string() + "' is not a regular file; expected a mesh file");
    const std::string ext = lower_extension(path);
    try {
        if (ext == ".msh") return read_gmsh(path.string());
        if (ext == ".inp") return read_abaqus(path.string());
        if (ext == ".k" || ext == ".key" || ext == ".dyn") return read_lsdyna(path.string());
    } catch (const InputError& e) {
        file.fail(std::string("cannot use this mesh: ") + e.what());
    }
    file.fail("unknown mesh file type '" + ext +
              "'; expected a Gmsh .msh, an Abaqus .inp or an LS-DYNA .k file");
}

}  // namespace

MeshData read_mesh_block(const YamlValue& mesh, const std::string& base_dir) {
    // First pass: only to find which variant this is; each variant then checks its own keys.
    if (!mesh.is_map())
        mesh.fail(
            "expected a map with either `generator` (plate, cylinder_panel, spherical_cap, "
            "annulus, square_tube) and its parameters, or `file`, got " +
            mesh.describe());
    const YamlMap any = mesh.open_map("mesh settings");
    const int kinds = any.count({"generator", "file"});
    if (kinds != 1)
        mesh.fail(kinds == 0 ? "needs either `generator` or `file`"
                             : "has both `generator` and `file`; keep exactly one");
    MeshData data;
    if (any.has("file")) {
        data = from_file(mesh, base_dir);
    } else {
        const YamlValue g = any.at("generator");
        const std::string name = g.choice(k_generators);
        if (name == "plate") data = plate(mesh);
        if (name == "cylinder_panel") data = cylinder_panel(mesh);
        if (name == "spherical_cap") data = spherical_cap(mesh);
        if (name == "annulus") data = annulus(mesh);
        if (name == "square_tube") data = square_tube(mesh);
    }
    check_mesh(data, mesh);
    return data;
}

void check_mesh(const MeshData& mesh, const YamlValue& mesh_key) {
    if (mesh.triangles.empty()) mesh_key.fail("the mesh has no triangles");
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
        if (!mesh.nodes[i].allFinite())
            mesh_key.fail("node " + std::to_string(i + 1) +
                          " of the mesh has a coordinate that is not a finite number");
    const auto n = static_cast<Index>(mesh.nodes.size());
    auto element_name = [&](std::size_t e) {
        std::string s = "element " + std::to_string(e + 1);
        if (e < mesh.element_tag.size())
            s += " (number " + std::to_string(mesh.element_tag[e]) + " in the mesh file)";
        return s;
    };
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const auto& t = mesh.triangles[e];
        for (const Index v : t)
            if (v < 0 || v >= n)
                mesh_key.fail(element_name(e) + " refers to a node that does not exist");
        const Vec3& a = mesh.nodes[static_cast<std::size_t>(t[0])];
        const Vec3& b = mesh.nodes[static_cast<std::size_t>(t[1])];
        const Vec3& c = mesh.nodes[static_cast<std::size_t>(t[2])];
        const Real longest2 =
            std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
        const Real area = 0.5 * (b - a).cross(c - a).norm();
        if (!(longest2 > 0) || area < 1e-12 * longest2)
            mesh_key.fail(element_name(e) +
                          " is degenerate (zero area: its corners coincide or are aligned); "
                          "every triangle needs a positive area");
    }
}

}  // namespace fpmshell
