// Speed of the FPM shell cycle (element loop + particle update), in element-steps per second:
// the elastic element (3 x 2 points) on a plate of ~10^4 and ~10^5 triangles, and the plastic
// element (5 Lobatto points through the thickness x 7 or 3 in the plane, every point yielding)
// on ~10^4 triangles; with 1 thread and with all threads.
//   ./build/bench/fpmshell_bench            (make bench)
// The counter "element_steps/s" is the figure reported in the README.
#include <benchmark/benchmark.h>

#include <random>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

using namespace fpmshell;

namespace {

Model plate(Index n) {
    PlateParams pp;
    pp.nx = pp.ny = n;
    pp.pattern = DiagonalPattern::Alternate;
    MeshData mesh = generate_plate(pp);
    Model m;
    m.title = "bench plate";
    m.nodes = mesh.nodes;
    m.triangles = mesh.triangles;
    m.materials.push_back({"steel", MaterialType::Elastic, 7800, 2.1e11, 0.3});
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

int use_threads(int threads) {
#ifdef _OPENMP
    omp_set_num_threads(threads > 0 ? threads : omp_get_num_procs());
    return omp_get_max_threads();
#else
    (void)threads;
    return 1;
#endif
}

void run_solver(benchmark::State& state, const Model& m, int used, int warm_up) {
    ExplicitSolver solver(m);
    for (int i = 0; i < warm_up; ++i) solver.step(1e30);  // leave the start-up steps out
    for (auto _ : state) solver.step(1e30);
    state.counters["elements"] = static_cast<double>(m.n_elements());
    state.counters["threads"] = used;
    state.counters["element_steps/s"] = benchmark::Counter(
        static_cast<double>(m.n_elements()) * static_cast<double>(state.iterations()),
        benchmark::Counter::kIsRate);
}

void elastic_plate(benchmark::State& state) {
    const int used = use_threads(static_cast<int>(state.range(1)));
    run_solver(state, plate(static_cast<Index>(state.range(0))), used, 5);
}

void plastic_plate(benchmark::State& state) {
    const int used = use_threads(static_cast<int>(state.range(2)));
    Model m = plate(static_cast<Index>(state.range(0)));
    Material& steel = m.materials[0];
    steel.type = MaterialType::J2Plastic;
    steel.yield_stress = 1e6;      // low, under a steady biaxial stretching and bending rate
    steel.tangent_modulus = 1e10;  // (initial velocity field, free plate): every point stays
    m.boundary.clear();            // plastic for the whole measurement, so the return mapping
    m.loads.clear();               // runs at every point of every step
    for (Index p = 0; p < static_cast<Index>(m.nodes.size()); ++p) {
        const Vec3& x = m.nodes[static_cast<std::size_t>(p)];
        InitialVelocity iv;
        iv.nodes = {p};
        const Real dx = x.x() - 0.5, dy = x.y() - 0.5;
        iv.velocity = Vec3(200 * dx, 100 * dy, 50 * (dx * dx + dy * dy));
        m.initial_conditions.push_back(iv);
    }
    m.sections[0].thickness_points = 5;
    m.sections[0].inplane_points = static_cast<int>(state.range(1));
    run_solver(state, m, used, 50);
}

}  // namespace

// 2 x 71^2 = 10 082 and 2 x 224^2 = 100 352 triangles; threads 1 and 0 (= all cores).
BENCHMARK(elastic_plate)->Args({71, 1})->Args({71, 0})->Args({224, 1})->Args({224, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime();
// 10 082 triangles, 5 x 7 and 5 x 3 points, threads 1 and 0; the same 300 steps after the
// warm-up for every variant (the plastic state evolves, so equal windows keep them comparable).
BENCHMARK(plastic_plate)->Args({71, 7, 1})->Args({71, 3, 1})->Args({71, 7, 0})->Args({71, 3, 0})
    ->Iterations(300)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
