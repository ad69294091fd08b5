// The models the benchmark program times, shared by the Google Benchmark cases
// (bench_elastic_plate.cpp, bench_square_tube.cpp) and the figure-of-merit table
// (perf_table.cpp) and the crash kernels (crash_kernels/): the clamped plate under pressure,
// its plastic variants, and the square tube.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "fpmshell/elements/bending_time_step.hpp"
#include "fpmshell/elements/lumped_inertia.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell::bench {

/// Unit square plate of 2 n^2 triangles (alternating diagonals), steel 2 mm, 3 in-plane x 2
/// thickness points (the elastic default section), every edge clamped, pressure 1 kPa.
inline Model elastic_plate_model(Index n) {
    PlateParams pp;
    pp.nx = pp.ny = n;
    pp.pattern = DiagonalPattern::Alternate;
    MeshData mesh = generate_plate(pp);
    Model m;
    m.title = "bench plate";
    m.nodes = mesh.nodes;
    m.triangles = mesh.triangles;
    m.materials.push_back({"steel", "elastic", 7800, 2.1e11, 0.3});
    m.sections.push_back({0, 0.002, 2, 3});
    m.element_section.assign(m.triangles.size(), 0);
    BoundaryCondition bc;
    bc.nodes = mesh.node_sets.at("boundary");
    bc.fixed = {true, true, true, true, true, true};
    m.boundary.push_back(bc);
    Load p;
    p.type = LoadType::Pressure;
    for (Index e = 0; e < m.n_elements(); ++e) p.elements.push_back(e);
    p.pressure = 1e3;
    m.loads.push_back(p);
    m.control.end_time = 1;
    return m;
}

/// The same plate, J2 plastic with 5 Lobatto points through the thickness x inplane_points (3 or
/// 7) in the plane. A low yield stress under a steady biaxial stretching and bending rate
/// (initial velocity field, free plate, no load) keeps every point plastic from the second step
/// on, so the return mapping runs at every point of every step.
inline Model plastic_plate_model(Index n, int inplane_points) {
    Model m = elastic_plate_model(n);
    Material& steel = m.materials[0];
    make_bilinear(steel, 1e6, 1e10);
    m.boundary.clear();
    m.loads.clear();
    for (Index p = 0; p < static_cast<Index>(m.nodes.size()); ++p) {
        const Vec3& x = m.nodes[static_cast<std::size_t>(p)];
        InitialVelocity iv;
        iv.nodes = {p};
        const Real dx = x.x() - 0.5, dy = x.y() - 0.5;
        iv.velocity = Vec3(200 * dx, 100 * dy, 50 * (dx * dx + dy * dy));
        m.initial_conditions.push_back(iv);
    }
    m.sections[0].thickness_points = 5;
    m.sections[0].inplane_points = inplane_points;
    return m;
}

/// Stable step of the plate model m at t = 0 (ExplicitSolver::stable_dt, from its first
/// elements: every triangle of the generated plate has the same shape), without building a
/// solver: time_step_scale x min(membrane L_c / c, bending step) (§6.4).
inline Real plate_stable_dt(const Model& m) {
    const Material& mat = m.materials[0];
    const Section& sec = m.sections[0];
    const Real c =
        std::sqrt(mat.youngs_modulus / (mat.density * (1 - mat.poisson_ratio * mat.poisson_ratio)));
    const Real f = mat.youngs_modulus / (1 - mat.poisson_ratio * mat.poisson_ratio);
    Mat3 rigidity;
    rigidity << f, f * mat.poisson_ratio, 0, f * mat.poisson_ratio, f, 0, 0, 0,
        f * (1 - mat.poisson_ratio) / 2;
    rigidity *= sec.thickness * sec.thickness * sec.thickness / 12;
    Real dt = 1e30;
    for (std::size_t e = 0; e < std::min<std::size_t>(2, m.triangles.size()); ++e) {
        const auto& t = m.triangles[e];
        const Vec3& p0 = m.nodes[static_cast<std::size_t>(t[0])];
        const Vec3& p1 = m.nodes[static_cast<std::size_t>(t[1])];
        const Vec3& p2 = m.nodes[static_cast<std::size_t>(t[2])];
        const Vec3 ex = (p1 - p0).normalized(), d = p2 - p0;
        const TriangleShape shape((p1 - p0).norm(), d.dot(ex), ex.cross(d).norm());
        const Real two_area = (p1 - p0).cross(d).norm();
        const Real lmax = std::sqrt(
            std::max({(p1 - p0).squaredNorm(), (p2 - p1).squaredNorm(), d.squaredNorm()}));
        const NodeInertiaShare share =
            lumped_node_share(mat.density, sec.thickness, 0.5 * two_area);
        const Real bending =
            bending_critical_dt(m.control.bending, shape, rigidity, share.mass, share.inertia);
        dt = std::min({dt, two_area / lmax / c, bending});
    }
    return m.control.time_step_scale * dt;
}

/// The motion of the steady plastic plates (steady_plastic_plate_model, the crash kernels): on
/// the unit plate, biaxial stretching (strain rates 2 : 1) and bending by one velocity field,
/// prescribed on `edge` and given as the initial velocity everywhere, at the rate that brings
/// the points to yield_stress after steps_to_yield steps of dt.
inline void impose_steady_flow(Model& m, const std::vector<Index>& edge, Real yield_stress,
                               int steps_to_yield, Real dt) {
    // strains e_x = 2 e, e_y = e: plane-stress von Mises stress 2.244 E e (nu = 0.3)
    const Real e_yield = yield_stress / (2.244 * m.materials[0].youngs_modulus);
    const Real rate = e_yield / (steps_to_yield * dt);
    auto velocity = [rate](const Vec3& x) {
        const Real dx = x.x() - 0.5, dy = x.y() - 0.5;
        return Vec3(2 * rate * dx, rate * dy, 0.5 * rate * (dx * dx + dy * dy));
    };
    for (Index p : edge) {
        BoundaryCondition bc;
        bc.nodes = {p};
        bc.prescribed = PrescribedKind::Velocity;
        bc.value = velocity(m.nodes[static_cast<std::size_t>(p)]);
        m.boundary.push_back(bc);
    }
    for (Index p = 0; p < static_cast<Index>(m.nodes.size()); ++p) {
        InitialVelocity iv;
        iv.nodes = {p};
        iv.velocity = velocity(m.nodes[static_cast<std::size_t>(p)]);
        m.initial_conditions.push_back(iv);
    }
}

/// A steady plastic flow for the figure-of-merit table (perf_table.cpp), the same at every mesh
/// size: the plate of elastic_plate_model, J2 plastic (sigma_y 250 MPa, E_t = E / 21), 5 Lobatto
/// points through the thickness x inplane_points, stretched biaxially (strain rates 2 : 1) and
/// bent by a uniform velocity field prescribed on the edges and given as the initial velocity
/// everywhere: a homogeneous motion that never unloads. The rate is set from the stable step so
/// that the points reach the yield surface after steps_to_yield steps at every mesh size; then
/// every point yields at every step with a trial overshoot of about 1 / steps_to_yield of the
/// yield radius (the regime of a crash run, one or two Newton iterations). plastic_plate_model
/// instead overshoots the yield radius many times at the first steps and its cost per step
/// falls several-fold over its first hundred steps as the hardening catches up.
inline Model steady_plastic_plate_model(Index n, int inplane_points, int steps_to_yield) {
    Model m = elastic_plate_model(n);
    Material& steel = m.materials[0];
    make_bilinear(steel, 250e6, 1e10);
    m.sections[0].thickness_points = 5;
    m.sections[0].inplane_points = inplane_points;
    m.loads.clear();
    const std::vector<Index> edge =
        m.boundary.at(0).nodes;  // the clamped edges of the elastic plate
    m.boundary.clear();
    impose_steady_flow(m, edge, 250e6, steps_to_yield, plate_stable_dt(m));
    return m;
}

/// bench/whole_run/plate_plastic.yaml, the plastic plate of the whole-run measure
/// (docs/performance.md: clamped, J2 5 x 3 points, a sudden pressure that makes it yield),
/// with 2 n^2 triangles.
inline Model whole_run_plastic_plate_model(Index n) {
    const std::string path =
        std::string(FPMSHELL_SOURCE_DIR) + "/bench/whole_run/plate_plastic.yaml";
    return read_model(path, {"mesh.nx=" + std::to_string(n), "mesh.ny=" + std::to_string(n)});
}

/// examples/square_tube/model.yaml (Johnson-Cook, 5 x 3 points, self-contact and the rigid
/// striker) with divisions across a face and along the tube.
inline Model square_tube_model(int divisions_width, int divisions_length) {
    const std::string path = std::string(FPMSHELL_SOURCE_DIR) + "/examples/square_tube/model.yaml";
    return read_model(path, {"mesh.divisions_width=" + std::to_string(divisions_width),
                             "mesh.divisions_length=" + std::to_string(divisions_length)});
}

}  // namespace fpmshell::bench
