// Measured peaks of this machine for the figure-of-merit table (perf_table.cpp): the
// floating-point throughput of a multiply-add loop compiled with the project's flags, the same
// with the widest FMA instructions the CPU has (a reference: the project is not built for them
// unless its flags say so), and the STREAM triad bandwidth on arrays far larger than the caches.
#pragma once

#include <cstddef>
#include <string>

namespace fpmshell::bench {

struct FlopPeak {
    double gflops = 0;  ///< best of the repeats, all threads together
};

/// a = a * x + y on independent double accumulators (throughput-bound), compiled like the rest
/// of the project: with the default x86-64 flags GCC emits packed SSE2 multiplies and adds
/// (2 flop per a * x + y, 2 lanes); with -mfma / -march=native it contracts them into FMAs.
/// `threads` threads each run `iterations` sweeps; best of `repeats`.
FlopPeak measure_flop_peak(int threads, long iterations, int repeats);

/// The same loop on the widest FMA the CPU has (AVX-512 or AVX2 + FMA, chosen at run time with
/// GCC target attributes). gflops 0 when the CPU or compiler has neither.
FlopPeak measure_isa_flop_peak(int threads, long iterations, int repeats);
/// Name of the instruction set measure_isa_flop_peak uses ("AVX-512 FMA", "AVX2 FMA", "none").
std::string isa_flop_name();

struct StreamPeak {
    double gbytes_per_s = 0;  ///< best triad of the repeats, STREAM convention: 24 B per index
};

/// STREAM triad a[i] = b[i] + s c[i] on three arrays of `n` doubles each (first-touch by the same
/// static OpenMP schedule), best of `repeats`.
StreamPeak measure_stream_triad(int threads, std::size_t n, int repeats);

/// Vector instruction set the project's flags target, from the predefined macros of this
/// translation unit (compiled with the same flags as the library).
std::string build_vector_isa();

}  // namespace fpmshell::bench
