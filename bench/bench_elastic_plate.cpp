// Speed of the FPM shell cycle (element loop + particle update), in element-steps per second:
// the elastic element (3 x 2 points) on a plate of ~10^4 and ~10^5 triangles, and the plastic
// element (5 Lobatto points through the thickness x 7 or 3 in the plane, every point yielding)
// on ~10^4 triangles; with 1 thread and with all threads.
//   ./build/bench/fpmshell_bench            (make bench)
// The counter "element_steps/s" is the figure reported in the README. The table of the figure
// of merit (ns per element-step, fraction of the machine's peak) is `fpmshell_bench --table`
// (perf_table.cpp).
#include <benchmark/benchmark.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "bench_models.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

using namespace fpmshell;

namespace {

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
    run_solver(state, bench::elastic_plate_model(static_cast<Index>(state.range(0))), used, 5);
}

void plastic_plate(benchmark::State& state) {
    const int used = use_threads(static_cast<int>(state.range(2)));
    const Model m = bench::plastic_plate_model(static_cast<Index>(state.range(0)),
                                               static_cast<int>(state.range(1)));
    run_solver(state, m, used, 50);
}

}  // namespace

// 2 x 71^2 = 10 082 and 2 x 224^2 = 100 352 triangles; threads 1 and 0 (= all cores).
BENCHMARK(elastic_plate)
    ->Args({71, 1})
    ->Args({71, 0})
    ->Args({224, 1})
    ->Args({224, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// 10 082 triangles, 5 x 7 and 5 x 3 points, threads 1 and 0; the same 300 steps after the
// warm-up for every variant (the plastic state evolves, so equal windows keep them comparable).
BENCHMARK(plastic_plate)
    ->Args({71, 7, 1})
    ->Args({71, 3, 1})
    ->Args({71, 7, 0})
    ->Args({71, 3, 0})
    ->Iterations(300)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
