// The figure-of-merit table (docs/performance.md): ns per element-step of the element
// loop and of the whole step, elastic and plastic, 10^3 to 10^6 elements, 1 thread and all,
// with the flops and bytes of each (kernel_costs.hpp) against the measured peaks of the machine
// (machine_peak.hpp).
//   fpmshell_bench --table [--max-elements N] [--threads N] [--quick]
#pragma once

namespace fpmshell::bench {

/// True when argv asks for the table (--table or --quick): main() then calls run_table
/// instead of Google Benchmark.
bool wants_table(int argc, char** argv);

/// Runs the measurements and prints the table on stdout (progress on stderr). Exit status.
int run_table(int argc, char** argv);

}  // namespace fpmshell::bench
