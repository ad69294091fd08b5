// Speed of the elastic FPM shell cycle (element loop + particle update), in element-steps per
// second, on a plate of ~10^4 and ~10^5 triangles, with 1 thread and with all threads.
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

void elastic_plate(benchmark::State& state) {
    const Index n = static_cast<Index>(state.range(0));
    const int threads = static_cast<int>(state.range(1));
#ifdef _OPENMP
    omp_set_num_threads(threads > 0 ? threads : omp_get_num_procs());
    const int used = omp_get_max_threads();
#else
    const int used = 1;
#endif
    const Model m = plate(n);
    ExplicitSolver solver(m);
    for (int i = 0; i < 5; ++i) solver.step(1e30);  // leave the start-up step out
    for (auto _ : state) solver.step(1e30);
    state.counters["elements"] = static_cast<double>(m.n_elements());
    state.counters["threads"] = used;
    state.counters["element_steps/s"] = benchmark::Counter(
        static_cast<double>(m.n_elements()) * static_cast<double>(state.iterations()),
        benchmark::Counter::kIsRate);
}

}  // namespace

// 2 x 71^2 = 10 082 and 2 x 224^2 = 100 352 triangles; threads 1 and 0 (= all cores).
BENCHMARK(elastic_plate)->Args({71, 1})->Args({71, 0})->Args({224, 1})->Args({224, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
