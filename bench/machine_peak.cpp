#include "machine_peak.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <memory>

#ifdef _OPENMP
#include <omp.h>
#endif

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define FPMSHELL_BENCH_X86 1
#endif

namespace fpmshell::bench {
namespace {

// Multiplier and addend of the sweeps, read at run time so that nothing is folded: acc = acc x + y
// converges to y / (1 - x) = 1 and never leaves the normal range.
volatile double g_x = 0.999999, g_y = 1e-6;
volatile double g_sink = 0;

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// 24 independent chains: with 2-lane SSE2 these are 12 packed multiply + add pairs per sweep,
// enough to cover the multiply + add latency (8 cycles) at 2 multiplies and 2 adds per cycle,
// and they fit the 16 xmm registers with x and y.
constexpr int k_portable_chains = 24;
constexpr double k_portable_flops_per_sweep = 2.0 * k_portable_chains;

double portable_sweep(long iterations, double x, double y) {
    std::array<double, k_portable_chains> acc;
    for (int j = 0; j < k_portable_chains; ++j) acc[static_cast<std::size_t>(j)] = 1.0 + 1e-3 * j;
    for (long i = 0; i < iterations; ++i)
        for (int j = 0; j < k_portable_chains; ++j)
            acc[static_cast<std::size_t>(j)] = acc[static_cast<std::size_t>(j)] * x + y;
    double s = 0;
    for (double a : acc) s += a;
    return s;
}

#ifdef FPMSHELL_BENCH_X86
// 16 zmm chains of 8 lanes: 2 FMA ports x 4 cycles latency need 8; 16 leave a margin.
constexpr int k_avx512_chains = 16;
constexpr double k_avx512_flops_per_sweep = 2.0 * 8 * k_avx512_chains;

__attribute__((target("avx512f"))) double avx512_sweep(long iterations, double x, double y) {
    const __m512d vx = _mm512_set1_pd(x), vy = _mm512_set1_pd(y);
    __m512d acc[k_avx512_chains];
    for (int j = 0; j < k_avx512_chains; ++j) acc[j] = _mm512_set1_pd(1.0 + 1e-3 * j);
    for (long i = 0; i < iterations; ++i)
        for (int j = 0; j < k_avx512_chains; ++j) acc[j] = _mm512_fmadd_pd(acc[j], vx, vy);
    __m512d s = acc[0];
    for (int j = 1; j < k_avx512_chains; ++j) s = _mm512_add_pd(s, acc[j]);
    alignas(64) double lanes[8];
    _mm512_store_pd(lanes, s);
    double sum = 0;
    for (double l : lanes) sum += l;
    return sum;
}

constexpr int k_avx2_chains = 12;
constexpr double k_avx2_flops_per_sweep = 2.0 * 4 * k_avx2_chains;

__attribute__((target("avx2,fma"))) double avx2_sweep(long iterations, double x, double y) {
    const __m256d vx = _mm256_set1_pd(x), vy = _mm256_set1_pd(y);
    __m256d acc[k_avx2_chains];
    for (int j = 0; j < k_avx2_chains; ++j) acc[j] = _mm256_set1_pd(1.0 + 1e-3 * j);
    for (long i = 0; i < iterations; ++i)
        for (int j = 0; j < k_avx2_chains; ++j) acc[j] = _mm256_fmadd_pd(acc[j], vx, vy);
    __m256d s = acc[0];
    for (int j = 1; j < k_avx2_chains; ++j) s = _mm256_add_pd(s, acc[j]);
    alignas(32) double lanes[4];
    _mm256_store_pd(lanes, s);
    return lanes[0] + lanes[1] + lanes[2] + lanes[3];
}

bool has_avx512() { return __builtin_cpu_supports("avx512f"); }
bool has_avx2_fma() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }
#endif

/// Every thread runs sweep(iterations); GFLOP/s of all threads together, best of the repeats.
template <class Sweep>
FlopPeak run_sweeps([[maybe_unused]] int threads, long iterations, int repeats,
                    double flops_per_sweep, Sweep sweep) {
    FlopPeak best;
    const double x = g_x, y = g_y;
    for (int r = 0; r < repeats; ++r) {
        double sink = 0;
        int ran = 0;
        const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel num_threads(threads) reduction(+ : sink, ran)
        {
            sink += sweep(iterations, x, y);
            ran += 1;
        }
        const double t = seconds_since(t0);
        g_sink = g_sink + sink;
        best.gflops = std::max(best.gflops,
                               ran * static_cast<double>(iterations) * flops_per_sweep / t * 1e-9);
    }
    return best;
}

}  // namespace

FlopPeak measure_flop_peak(int threads, long iterations, int repeats) {
    return run_sweeps(threads, iterations, repeats, k_portable_flops_per_sweep, portable_sweep);
}

FlopPeak measure_isa_flop_peak(int threads, long iterations, int repeats) {
#ifdef FPMSHELL_BENCH_X86
    if (has_avx512())
        return run_sweeps(threads, iterations, repeats, k_avx512_flops_per_sweep, avx512_sweep);
    if (has_avx2_fma())
        return run_sweeps(threads, iterations, repeats, k_avx2_flops_per_sweep, avx2_sweep);
#else
    (void)threads;
    (void)iterations;
    (void)repeats;
#endif
    return {};
}

std::string isa_flop_name() {
#ifdef FPMSHELL_BENCH_X86
    if (has_avx512()) return "AVX-512 FMA (8 lanes)";
    if (has_avx2_fma()) return "AVX2 FMA (4 lanes)";
#endif
    return "none";
}

StreamPeak measure_stream_triad([[maybe_unused]] int threads, std::size_t n, int repeats) {
    const std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
    double* pa = a.get();
    double* pb = b.get();
    double* pc = c.get();
    const long nn = static_cast<long>(n);
    // first touch with the schedule of the triad: every thread's pages are its own
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long i = 0; i < nn; ++i) {
        pa[i] = 0;
        pb[i] = 1;
        pc[i] = 2;
    }
    const double s = 3 * g_x;
    StreamPeak best;
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static) num_threads(threads)
        for (long i = 0; i < nn; ++i) pa[i] = pb[i] + s * pc[i];
        const double t = seconds_since(t0);
        best.gbytes_per_s = std::max(best.gbytes_per_s, 24.0 * static_cast<double>(n) / t * 1e-9);
    }
    g_sink = g_sink + pa[n / 2];
    return best;
}

std::string build_vector_isa() {
#if defined(__AVX512F__)
    std::string isa = "AVX-512";
#elif defined(__AVX2__)
    std::string isa = "AVX2";
#elif defined(__AVX__)
    std::string isa = "AVX";
#elif defined(__SSE2__)
    std::string isa = "SSE2";
#else
    std::string isa = "scalar";
#endif
#if defined(__FMA__)
    isa += " + FMA";
#else
    isa += ", no FMA";
#endif
    return isa;
}

}  // namespace fpmshell::bench
