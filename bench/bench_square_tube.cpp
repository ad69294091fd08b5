// Cost of contact on the square tube (examples/square_tube/model.yaml): element-steps
// per second of the whole step with self-contact and the rigid striker, and the share of the
// step spent in contact (search + Lagrange-multiplier sweeps), on the 15 x 64 mesh after 4000
// steps (about 1.7 ms: the first fold is forming against the striker) and the paper's 30 x 128.
// The share over a whole crush is in summary.json ("contact": "share_of_time_loop") of a run.
#include <benchmark/benchmark.h>

#include <chrono>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "bench_models.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

using namespace fpmshell;

namespace {

void square_tube(benchmark::State& state) {
#ifdef _OPENMP
    omp_set_num_threads(state.range(2) > 0 ? static_cast<int>(state.range(2))
                                           : omp_get_num_procs());
    const int used = omp_get_max_threads();
#else
    const int used = 1;
#endif
    const Model m = bench::square_tube_model(static_cast<int>(state.range(0)),
                                             static_cast<int>(state.range(1)));
    ExplicitSolver solver(m);
    for (int i = 0; i < 4000; ++i) solver.step(1e30);
    const double contact0 = solver.contact_statistics()->seconds;
    double wall = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        solver.step(1e30);
        wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    state.counters["elements"] = static_cast<double>(m.n_elements());
    state.counters["threads"] = used;
    state.counters["element_steps/s"] = benchmark::Counter(
        static_cast<double>(m.n_elements()) * static_cast<double>(state.iterations()),
        benchmark::Counter::kIsRate);
    state.counters["contact_share"] = (solver.contact_statistics()->seconds - contact0) / wall;
    state.counters["contacts"] = static_cast<double>(solver.contact_statistics()->active);
}

}  // namespace

// (divisions across a face, along the tube, threads: 0 = all cores); 1000 steps measured.
BENCHMARK(square_tube)
    ->Args({15, 64, 1})
    ->Args({15, 64, 0})
    ->Args({30, 128, 1})
    ->Iterations(1000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
