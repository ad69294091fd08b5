// Time to write one VTU frame of the elastic plate of 2 n^2 triangles (n = 708: 1.0 x 10^6
// triangles) after a few steps, as a run writes it (driver/field_series.cpp): the standard fields
// gathered from the solver into the frame of the last iteration (field_frame, on the OpenMP
// threads) and the file written (write_vtu), in each encoding: raw appended (the default),
// raw + zlib, base64. Each frame is a new file in $TMPDIR (default /tmp), removed untimed.
//   ./build/bench/fpmshell_bench --benchmark_filter=vtu_frame
// Counters: MB (the file's size), MB/s. vtu_frame_gather times field_frame alone.
// docs/performance.md quotes the times.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "bench_models.hpp"
#include "fpmshell/driver/output_fields.hpp"
#include "fpmshell/io/vtu_writer.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

using namespace fpmshell;

namespace {

void vtu_frame(benchmark::State& state) {
    const Model m = bench::elastic_plate_model(static_cast<Index>(state.range(0)));
    ExplicitSolver solver(m);
    for (int i = 0; i < 3; ++i) solver.step(1e30);  // some motion in every field
    const VtuFormat formats[] = {
        VtuEncoding::Raw, {VtuEncoding::Raw, VtuCompression::Zlib}, VtuEncoding::Base64};
    const VtuFormat format = formats[state.range(1)];
    const char* tmp = std::getenv("TMPDIR");
    const std::filesystem::path dir =
        std::filesystem::path(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp");
    const std::string stem = "fpmshell_bench_frame_" + std::to_string(::getpid()) + "_";
    const std::vector<OutputField> fields = standard_fields(m);
    FieldFrame frame;  // reused from frame to frame, as FieldSeries does
    double bytes = 0;
    long n_frame = 0;
    for (auto _ : state) {
        // a new file per frame, as a run writes frame_00001.vtu, frame_00002.vtu, ...
        const std::filesystem::path file = dir / (stem + std::to_string(n_frame++) + ".vtu");
        field_frame(fields, {m, solver, solver.state().x}, solver.time(), frame);
        write_vtu(file, frame, format);
        state.PauseTiming();  // the file is removed outside the timed part
        bytes = static_cast<double>(std::filesystem::file_size(file));
        std::filesystem::remove(file);
        state.ResumeTiming();
    }
    state.counters["triangles"] = static_cast<double>(m.n_elements());
    state.counters["MB"] = bytes / 1e6;
    state.counters["MB/s"] = benchmark::Counter(
        bytes / 1e6 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.SetLabel(state.range(1) == 0 ? "raw" : state.range(1) == 1 ? "raw+zlib" : "base64");
}

/// The part of vtu_frame that gathers the fields from the solver (field_frame), without the file.
void vtu_frame_gather(benchmark::State& state) {
    const Model m = bench::elastic_plate_model(static_cast<Index>(state.range(0)));
    ExplicitSolver solver(m);
    for (int i = 0; i < 3; ++i) solver.step(1e30);
    const std::vector<OutputField> fields = standard_fields(m);
    FieldFrame frame;
    for (auto _ : state) {
        field_frame(fields, {m, solver, solver.state().x}, solver.time(), frame);
        benchmark::DoNotOptimize(frame.point_data.data());
    }
    state.counters["triangles"] = static_cast<double>(m.n_elements());
}

}  // namespace

BENCHMARK(vtu_frame_gather)->Arg(708)->Unit(benchmark::kMillisecond)->UseRealTime();

// n = 708: 1 002 528 triangles; (n, format: 0 raw, 1 raw + zlib, 2 base64)
BENCHMARK(vtu_frame)
    ->Args({708, 0})
    ->Args({708, 1})
    ->Args({708, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
