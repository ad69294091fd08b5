// Entry point of fpmshell_bench: the Google Benchmark cases (bench_elastic_plate.cpp,
// bench_square_tube.cpp; `make bench`), or with --table / --quick the figure-of-merit table
// (perf_table.cpp).
#include <benchmark/benchmark.h>

#include "perf_table.hpp"

int main(int argc, char** argv) {
    if (fpmshell::bench::wants_table(argc, argv)) return fpmshell::bench::run_table(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
