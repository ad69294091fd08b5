// The figure-of-merit table; see perf_table.hpp.
//
// Whole step: ExplicitSolver::step (elements + normals + loads + particle update + contact),
// timed alone. Element loop: ShellElements::compute alone, on a twin of the solver's elements
// given the solver's current path element (x_prev, x, dtheta: an untimed copy); see
// measure_plate. Flops and bytes: kernel_costs.hpp; peaks: machine_peak.cpp.
#include "perf_table.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "bench_models.hpp"
#include "fpmshell/materials/j2/j2_parameters.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "fpmshell/solver/shell_elements.hpp"
#include "kernel_costs.hpp"
#include "machine_peak.hpp"

#ifndef FPMSHELL_BENCH_FLAGS
#define FPMSHELL_BENCH_FLAGS "(unknown)"
#endif
#ifndef FPMSHELL_BENCH_BUILD_TYPE
#define FPMSHELL_BENCH_BUILD_TYPE "(unknown)"
#endif

namespace fpmshell::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

/// CPU time of the whole process (every thread), seconds.
double process_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

int processors() {
#ifdef _OPENMP
    return omp_get_num_procs();
#else
    return 1;
#endif
}

void use_threads(int threads) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
}

// The steady plastic plate (bench_models.hpp): its points reach the yield surface after this
// many steps; the element-loop and whole-step samples start 2 steps later.
constexpr int k_steps_to_yield = 10;
// Steps per sample at most: the plastic plate stretches by ~0.1 % per step, and a window of a few
// tens of steps keeps every mesh size in the same state (strain, distortion, bending ratio).
constexpr long k_max_steps_per_sample = 10;
// Steps per sample at least: the first step of a sample starts cold (the other measure ran in
// between: the element-loop twin has arrays of its own), which on 10^5 and 10^6 elements, one
// step per sample, made the whole step 20-30 % dearer than the time loop of `fpmshell run`.
constexpr long k_min_steps_per_sample = 3;
// The plastic plate under pressure of the whole-run measure (bench/whole_run/plate_plastic.yaml)
// is sampled from this step on: the middle of the ~100 steps run.py times.
constexpr long k_whole_run_warm_up = 50;

struct Options {
    bool quick = false;
    long max_elements = 2'000'000;
    int all_threads = 1;
    int tube_width = 15, tube_length = 64;  // bench_square_tube.cpp's README figure
    long tube_warm_up = 4000;               // the first fold forming against the striker
    bool tube = true;
};

struct PeakSet {
    double flops_build = 0, flops_isa = 0, stream = 0;  // GFLOP/s, GFLOP/s, GB/s
};

struct Row {
    int order = 0;  // kernel order in the table
    std::string kernel;
    Index elements = 0;
    int threads = 1;
    double ns = 0;  // median ns per element-step
    double flops = 0, bytes = 0;
    int samples = 0;
    long steps_per_sample = 0;
    double cpu_share = 0;  // process CPU time / (threads x wall time) over the samples
};

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

cost::MaterialCost material_cost(const Model& m, double yield_fraction, int newton_evaluations) {
    const Material& mat = m.materials.at(static_cast<std::size_t>(m.sections.at(0).material));
    cost::MaterialCost c;
    c.plastic = mat.plastic();
    c.yield_fraction = yield_fraction;
    c.newton_evaluations = newton_evaluations;
    const J2Parameters* j2 = j2_parameters(mat);
    c.johnson_cook = j2 && j2->flow.kind == FlowStress::Kind::JohnsonCook;
    c.rate = j2 && (j2->rate.kind == RateFactor::Kind::JohnsonCook ||
                    j2->rate.kind == RateFactor::Kind::CowperSymonds);
    return c;
}

cost::StepExtras step_extras(const Model& m) {
    cost::StepExtras x;
    for (const Load& l : m.loads) x.pressure = x.pressure || l.type == LoadType::Pressure;
    x.contact = !m.contacts.empty();
    return x;
}

/// Share of sampled (element, thickness point) pairs whose equivalent plastic strain (averaged
/// over the in-plane points) grew over a window: over one step, about the share of the points
/// that yield (an upper bound: one yielding in-plane point of the pair is enough).
class YieldProbe {
public:
    void start(const ShellElements& el) {
        const Index stride = std::max<Index>(1, el.size() / 2000);
        entries_.clear();
        for (Index e = 0; e < el.size(); e += stride)
            for (int k = 0; k < el.thickness_points(e); ++k)
                entries_.push_back({e, k, el.plastic_strain(e, k)});
    }
    [[nodiscard]] double fraction(const ShellElements& el) const {
        if (entries_.empty()) return 0;
        long grew = 0;
        for (const Entry& x : entries_) grew += el.plastic_strain(x.e, x.k) > x.before;
        return static_cast<double>(grew) / static_cast<double>(entries_.size());
    }

private:
    struct Entry {
        Index e;
        int k;
        Real before;
    };
    std::vector<Entry> entries_;
};

/// Element loop and whole step of one plate model, every thread count.
/// Whole-step samples time solver.step() alone, as a run would. Element-loop samples copy the
/// solver's current path element into the twin's particle state (untimed) and time the twin's
/// compute() on it (batch times in a row on the small meshes: its material points keep moving,
/// the kinematics are those of one step). During the warm-up the twin computes every path
/// element of the solver, so its material points carry the same history; afterwards it misses
/// the steps of the whole-step samples, which changes nothing the cost depends on here: the
/// elastic update is linear, and the steady plastic plate loads every point proportionally, so
/// the twin's points stay on the yield surface (checked: its yielding share is printed).
/// warm_up_steps < 0: the default (the steady plastic plate's first yield + 2 steps, 5 elastic);
/// every_point_yields: the flop counts take every point as yielding (the steady plate), else the
/// share measured at a step after the samples.
/// Before a one-thread sample of a round after the first (which follows a sample on more
/// threads): libgomp's idle threads spin for some 20 ms after a parallel region (3e5 pause
/// instructions) and took the second core from the one-thread sample (its rows showed
/// 130-160 % CPU). They fall asleep meanwhile.
void let_idle_threads_sleep(int threads, int round) {
    if (threads == 1 && round > 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
}

void measure_plate(const Model& m, int loop_order, const std::string& loop_name, int step_order,
                   const std::string& step_name, const Options& o, const std::vector<int>& threads,
                   std::vector<Row>& rows, std::vector<std::string>& notes, long warm_up_steps = -1,
                   bool every_point_yields = true) {
    const Index ne = m.n_elements();
    const auto t_setup = Clock::now();
    ExplicitSolver solver(m);
    const MeshTopology topology(m);
    ShellElements twin(m, topology);
    ParticleState ps = solver.state();
    const double setup_s = seconds(t_setup, Clock::now());
    const double ppe = static_cast<double>(ps.size()) / static_cast<double>(ne);
    const bool plastic = m.materials[0].plastic();
    const double target = o.quick ? 2e4 : 1e5;  // element-steps per sample
    const long batch =
        std::clamp<long>(static_cast<long>(std::ceil(target / static_cast<double>(ne))),
                         k_min_steps_per_sample, k_max_steps_per_sample);
    const int repeats = o.quick ? 3 : (ne > 500'000 ? 3 : 5);
    const long warm_up = warm_up_steps >= 0 ? warm_up_steps
                         : plastic          ? k_steps_to_yield + 2
                                            : (ne > 500'000 ? 3 : 5);
    const Real a_s = m.damping.stiffness;

    auto sync_twin = [&] {
        const ParticleState& s = solver.state();
        ps.x_prev = s.x_prev;  // same sizes: plain copies, no allocation
        ps.x = s.x;
        ps.dtheta = s.dtheta;
        ps.drill_axis = s.drill_axis;
    };
    auto twin_compute = [&] {
        const Real dt = solver.last_dt();
        (void)twin.compute(ps, (a_s > 0 && dt > 0) ? a_s / dt : 0.0, dt);
    };
    std::fprintf(
        stderr,
        "  %s, %d elements: set-up %.1f s, warm-up %ld steps, %d x %ld steps per thread count\n",
        step_name.c_str(), ne, setup_s, warm_up, repeats, batch);
    use_threads(threads.back());
    for (long i = 0; i < warm_up; ++i) {  // the twin in step with the solver
        sync_twin();
        twin_compute();
        solver.step(1e30);
    }

    struct Sample {
        std::vector<double> ns;
        double wall = 0, cpu = 0;
    };
    std::map<int, Sample> loop, step;
    const double es = static_cast<double>(batch) * static_cast<double>(ne);
    for (int r = 0; r < repeats; ++r) {
        for (int t : threads) {
            use_threads(t);
            let_idle_threads_sleep(t, r);
            double c0 = process_cpu_seconds();
            auto t0 = Clock::now();
            for (long i = 0; i < batch; ++i) solver.step(1e30);
            double wall = seconds(t0, Clock::now());
            step[t].ns.push_back(wall * 1e9 / es);
            step[t].wall += wall;
            step[t].cpu += process_cpu_seconds() - c0;

            sync_twin();
            c0 = process_cpu_seconds();
            t0 = Clock::now();
            for (long i = 0; i < batch; ++i) twin_compute();
            wall = seconds(t0, Clock::now());
            loop[t].ns.push_back(wall * 1e9 / es);
            loop[t].wall += wall;
            loop[t].cpu += process_cpu_seconds() - c0;
        }
    }
    // the share of the points yielding at one step and at one compute of the twin (untimed)
    double yield_step = 1.0;
    if (plastic) {
        YieldProbe probe;
        probe.start(solver.elements());
        solver.step(1e30);
        yield_step = probe.fraction(solver.elements());
        sync_twin();
        probe.start(twin);
        twin_compute();
        const double yield_loop = probe.fraction(twin);
        char buf[240];
        std::snprintf(buf, sizeof buf,
                      "%s, %d elements: %.1f %% of the sampled points yield at a step (step %ld), "
                      "%.1f %% at a compute "
                      "of the element-loop twin",
                      step_name.c_str(), ne, 100 * yield_step, solver.steps(), 100 * yield_loop);
        notes.push_back(buf);
    }

    const Section& sec = m.sections[0];
    // the plastic counts take every point as yielding where the steady plate does (notes)
    const cost::MaterialCost mc = material_cost(m, every_point_yields ? 1.0 : yield_step,
                                                cost::k_j2_newton_evaluations_plate);
    const double loop_flops =
        cost::element_loop_flops(sec.inplane_points, sec.thickness_points, m.control.bending, mc);
    const double loop_bytes =
        cost::element_loop_bytes(sec.inplane_points * sec.thickness_points, ppe);
    const cost::StepExtras extras = step_extras(m);
    for (int t : threads) {
        rows.push_back({loop_order, loop_name, ne, t, median(loop[t].ns), loop_flops, loop_bytes,
                        repeats, batch, loop[t].cpu / (t * loop[t].wall)});
        rows.push_back({step_order, step_name, ne, t, median(step[t].ns),
                        loop_flops + cost::step_rest_flops(ppe, extras),
                        loop_bytes + cost::step_rest_bytes(ppe, extras), repeats, batch,
                        step[t].cpu / (t * step[t].wall)});
    }
}

/// Whole step of the square tube with contact.
void measure_tube(int order, const Options& o, const std::vector<int>& threads,
                  std::vector<Row>& rows, std::vector<std::string>& notes) {
    const Model m = square_tube_model(o.tube_width, o.tube_length);
    const Index ne = m.n_elements();
    ExplicitSolver solver(m);
    const double ppe = static_cast<double>(solver.state().size()) / static_cast<double>(ne);
    const long warm_up = o.quick ? 100 : o.tube_warm_up;
    const long batch = o.quick ? 10 : 100;
    const int repeats = o.quick ? 3 : 5;
    std::fprintf(
        stderr,
        "  square tube %dx%d, %d elements: warm-up %ld steps, %d x %ld steps per thread count\n",
        o.tube_width, o.tube_length, ne, warm_up, repeats, batch);
    use_threads(threads.back());
    for (long i = 0; i < warm_up; ++i) solver.step(1e30);
    std::map<int, std::vector<double>> step_ns;
    std::map<int, double> step_total, contact_total, cpu_total;
    const long first_timed = solver.steps();
    for (int r = 0; r < repeats; ++r) {
        for (int t : threads) {
            use_threads(t);
            let_idle_threads_sleep(t, r);
            const double c0 =
                solver.contact_statistics() ? solver.contact_statistics()->seconds : 0.0;
            const double cpu0 = process_cpu_seconds();
            const auto t0 = Clock::now();
            for (long i = 0; i < batch; ++i) solver.step(1e30);
            const double s = seconds(t0, Clock::now());
            cpu_total[t] += process_cpu_seconds() - cpu0;
            const double c1 =
                solver.contact_statistics() ? solver.contact_statistics()->seconds : 0.0;
            step_ns[t].push_back(s * 1e9 / (static_cast<double>(batch) * static_cast<double>(ne)));
            step_total[t] += s;
            contact_total[t] += c1 - c0;
        }
    }
    const long last_timed = solver.steps();
    const double t_end = solver.time();
    // the share of the points yielding at a step, over 10 more (untimed) steps
    YieldProbe probe;
    double yield = 0;
    for (int i = 0; i < 10; ++i) {
        probe.start(solver.elements());
        solver.step(1e30);
        yield += 0.1 * probe.fraction(solver.elements());
    }
    const Section& sec = m.sections[0];
    const double flops =
        cost::element_loop_flops(sec.inplane_points, sec.thickness_points, m.control.bending,
                                 material_cost(m, yield, cost::k_j2_newton_evaluations_tube)) +
        cost::step_rest_flops(ppe, step_extras(m));
    const double bytes = cost::element_loop_bytes(sec.inplane_points * sec.thickness_points, ppe) +
                         cost::step_rest_bytes(ppe, step_extras(m));
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "square tube %dx%d (%d elements, timed steps %ld-%ld, t = %.2f ms): %.1f %% of "
                  "the sampled points yield "
                  "at a step; %ld active contacts at the end",
                  o.tube_width, o.tube_length, ne, first_timed, last_timed, t_end * 1e3,
                  100 * yield,
                  solver.contact_statistics() ? solver.contact_statistics()->active : 0L);
    notes.push_back(buf);
    for (int t : threads) {
        std::snprintf(
            buf, sizeof buf,
            "square tube, %d thread%s: contact (search + multipliers, serial) %.1f %% of the step",
            t, t > 1 ? "s" : "", 100 * contact_total[t] / step_total[t]);
        notes.push_back(buf);
        rows.push_back({order, "whole step, square tube + contact (5x3 JC)", ne, t,
                        median(step_ns[t]), flops, bytes, repeats, batch,
                        cpu_total[t] / (t * step_total[t])});
    }
}

std::string read_first_line_with(const std::string& path, const std::string& key) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(key, 0) == 0) {
            const auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    return "";
}

std::string read_file_line(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    return line;
}

void print_usage() {
    std::printf(
        "fpmshell_bench --table [--max-elements N] [--threads N] [--tube WxL | --no-tube] "
        "[--quick]\n"
        "  --table           the figure-of-merit table of docs/performance.md: element loop and "
        "whole step, ns per\n"
        "                    element-step, flops and bytes per element-step, fraction of the "
        "measured peaks\n"
        "  --max-elements N  skip the plate meshes of nominal size above N (10^3, 10^4, 10^5, 10^6 "
        "elements:\n"
        "                    --max-elements 100000 skips the 10^6 rows)\n"
        "  --threads N       the 'all threads' count (default: every processor)\n"
        "  --tube WxL        square tube divisions across a face x along (default 15x64)\n"
        "  --no-tube         skip the square tube row\n"
        "  --quick           smoke run: 10^3 and 10^4 plates, short windows, small peak arrays\n"
        "Without --table / --quick the program runs the Google Benchmark cases (make bench).\n");
}

}  // namespace

bool wants_table(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "--table") || !std::strcmp(argv[i], "--quick")) return true;
    return false;
}

int run_table(int argc, char** argv) {
    Options o;
    o.all_threads = processors();
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "%s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--table") continue;
        if (a == "--quick") {
            o.quick = true;
        } else if (a == "--max-elements") {
            o.max_elements = std::atol(value().c_str());
        } else if (a == "--threads") {
            o.all_threads = std::max(1, std::atoi(value().c_str()));
        } else if (a == "--tube") {
            const std::string v = value();
            if (std::sscanf(v.c_str(), "%dx%d", &o.tube_width, &o.tube_length) != 2) {
                std::fprintf(stderr, "--tube expects WxL, e.g. 15x64\n");
                return 2;
            }
        } else if (a == "--no-tube") {
            o.tube = false;
        } else if (a == "--help" || a == "-h") {
            print_usage();
            return 0;
        } else {
            std::fprintf(stderr, "unknown option %s\n", a.c_str());
            print_usage();
            return 2;
        }
    }
    std::vector<int> threads{1};
    if (o.all_threads > 1) threads.push_back(o.all_threads);
    const auto t_start = Clock::now();

    // ---- peaks ----
    std::fprintf(stderr, "measuring the peaks\n");
    auto elapsed = [&t_start] { return seconds(t_start, Clock::now()); };
    const long sweeps = o.quick ? 10'000'000 : 100'000'000;
    const std::size_t stream_n =
        o.quick ? (std::size_t{32} << 20) : (std::size_t{96} << 20);  // doubles per array
    std::map<int, PeakSet> peak;
    for (int t : threads) {
        peak[t].flops_build = measure_flop_peak(t, sweeps, 3).gflops;
        peak[t].flops_isa = measure_isa_flop_peak(t, sweeps, 3).gflops;
        peak[t].stream = measure_stream_triad(t, stream_n, o.quick ? 3 : 5).gbytes_per_s;
    }

    // ---- kernels ----
    std::vector<Row> rows;
    std::vector<std::string> notes;
    // (nominal size, n): 2 n^2 = 968, 10 082, 100 352, 999 698 triangles
    std::vector<std::pair<long, Index>> sizes{
        {1'000, 22}, {10'000, 71}, {100'000, 224}, {1'000'000, 707}};
    if (o.quick) sizes.resize(2);
    for (const auto& [nominal, n] : sizes) {
        if (nominal > o.max_elements) continue;
        std::fprintf(stderr, "[%4.0f s] plate %d x %d\n", elapsed(), n, n);
        measure_plate(elastic_plate_model(n), 0, "element loop, elastic 3x2", 4,
                      "whole step, elastic 3x2 plate", o, threads, rows, notes);
        measure_plate(whole_run_plastic_plate_model(n), 1,
                      "element loop, plastic 5x3, plate under pressure", 5,
                      "whole step, plastic 5x3 plate under pressure", o, threads, rows, notes,
                      k_whole_run_warm_up, false);
        measure_plate(steady_plastic_plate_model(n, 3, k_steps_to_yield), 2,
                      "element loop, plastic 5x3, every point yielding", 6,
                      "whole step, plastic 5x3 plate, every point yielding", o, threads, rows,
                      notes);
        measure_plate(steady_plastic_plate_model(n, 7, k_steps_to_yield), 3,
                      "element loop, plastic 5x7, every point yielding", 7,
                      "whole step, plastic 5x7 plate, every point yielding", o, threads, rows,
                      notes);
    }
    if (o.tube) {
        std::fprintf(stderr, "[%4.0f s] square tube\n", elapsed());
        measure_tube(8, o, threads, rows, notes);
    }
    std::fprintf(stderr, "[%4.0f s] done\n", elapsed());
    std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
        if (a.order != b.order) return a.order < b.order;
        if (a.elements != b.elements) return a.elements < b.elements;
        return a.threads < b.threads;
    });

    // ---- print ----
    const std::string cpu = read_first_line_with("/proc/cpuinfo", "model name");
    const std::string l3 = read_file_line("/sys/devices/system/cpu/cpu0/cache/index3/size");
    std::printf("## fpmshell figure of merit (fpmshell_bench --table%s)\n\n",
                o.quick ? " --quick" : "");
    std::printf("- machine: %s, %d processors for OpenMP, L3 %s\n", cpu.empty() ? "?" : cpu.c_str(),
                processors(), l3.empty() ? "?" : l3.c_str());
#if defined(__clang__)
    std::printf("- compiler: clang %s; build type %s; flags: %s\n", __VERSION__,
                FPMSHELL_BENCH_BUILD_TYPE, FPMSHELL_BENCH_FLAGS);
#elif defined(__GNUC__)
    std::printf("- compiler: GCC %s; build type %s; flags: %s\n", __VERSION__,
                FPMSHELL_BENCH_BUILD_TYPE, FPMSHELL_BENCH_FLAGS);
#endif
    std::printf("- vector instructions of the build (the library and the FMA loop alike): %s\n\n",
                build_vector_isa().c_str());
    std::printf(
        "Peaks (best of the repeats). FMA loop: a = a x + y on independent double accumulators, "
        "compiled with\n"
        "the flags above; ISA FMA: the same with %s (GCC target attribute, a reference only);\n"
        "STREAM triad a = b + s c on 3 arrays of %.0f MiB (24 B per index, write-allocate not "
        "counted).\n\n",
        isa_flop_name().c_str(), static_cast<double>(stream_n) * 8.0 / (1 << 20));
    std::printf(
        "| threads | FMA loop, build flags (GFLOP/s) | ISA FMA (GFLOP/s) | STREAM triad (GB/s) "
        "|\n");
    std::printf("|---:|---:|---:|---:|\n");
    for (int t : threads)
        std::printf("| %d | %.1f | %.1f | %.1f |\n", t, peak[t].flops_build, peak[t].flops_isa,
                    peak[t].stream);
    std::printf("\n");
    std::printf(
        "| kernel | elements | threads | ns / element-step | element-steps / s | flop / "
        "element-step | "
        "B / element-step | GFLOP/s | GB/s | %% FMA peak (build) | %% ISA peak | %% STREAM | %% "
        "CPU |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Row& r : rows) {
        const PeakSet& p = peak[r.threads];
        const double gflops = r.flops / r.ns, gbs = r.bytes / r.ns;  // flop / ns = GFLOP/s
        const double rate = 1e9 / r.ns;
        char rate_s[32];
        if (rate >= 1e6)
            std::snprintf(rate_s, sizeof rate_s, "%.2f M", rate * 1e-6);
        else
            std::snprintf(rate_s, sizeof rate_s, "%.0f k", rate * 1e-3);
        std::printf(
            "| %s | %d | %d | %.0f | %s | %.0f | %.0f | %.2f | %.2f | %.1f | %.1f | %.1f | %.0f "
            "|\n",
            r.kernel.c_str(), r.elements, r.threads, r.ns, rate_s, r.flops, r.bytes, gflops, gbs,
            p.flops_build > 0 ? 100 * gflops / p.flops_build : 0.0,
            p.flops_isa > 0 ? 100 * gflops / p.flops_isa : 0.0,
            p.stream > 0 ? 100 * gbs / p.stream : 0.0, 100 * r.cpu_share);
    }
    std::printf("\nNotes\n\n");
    std::printf(
        "- ns / element-step: median of the samples (5 per row, 3 for 10^6 elements and --quick), "
        "each sample a run of\n"
        "  steps of about %.0e element-steps (%ld to %ld steps). Whole step: ExplicitSolver::step. "
        "Element loop:\n"
        "  ShellElements::compute alone, on a twin of the solver's elements given the solver's "
        "current path element\n"
        "  (untimed copy; on the small meshes computed up to %ld times in a row, its material "
        "points moving on).\n"
        "- Plates: 2 n^2 triangles, n = 22, 71, 224, 707. Elastic: the clamped plate under "
        "pressure (bench_elastic_plate.cpp),\n"
        "  DKT, 3 x 2 points. Plastic under pressure: the plate of the whole-run measure "
        "(bench/whole_run/\n"
        "  plate_plastic.yaml: clamped, J2 5 x 3 points, a sudden pressure), sampled from step %ld "
        "on (the issue's\n"
        "  plastic whole-run and kernel targets are for this model; the share of its points that "
        "yield is in the\n"
        "  notes). Every point yielding: steady_plastic_plate_model (bench_models.hpp), J2 "
        "perfectly plastic, a\n"
        "  homogeneous biaxial stretch + bending prescribed on the edges, its rate set from the "
        "stable step so that\n"
        "  every size yields at step %d and then every point yields at every step with the same "
        "trial overshoot\n"
        "  (~10 %% of the yield radius); samples start at step %d: the cost of plasticity at its "
        "worst. (The\n"
        "  plastic_plate of the Google benchmark overshoots its 1 MPa yield stress many times over "
        "at first: its\n"
        "  cost per step falls ~10x over its first 200 steps, and differently on every mesh.) "
        "Square tube:\n"
        "  bench_square_tube.cpp's model.\n",
        o.quick ? 2e4 : 1e5, k_min_steps_per_sample, k_max_steps_per_sample, k_max_steps_per_sample,
        k_whole_run_warm_up, k_steps_to_yield, k_steps_to_yield + 2);
    std::printf(
        "- Flop and byte counts are analytic (bench/kernel_costs.hpp; no hardware counters on this "
        "machine), +-20 %%.\n"
        "  Flops: add / sub / mul / div / sqrt = 1, log / pow = %.0f; per element: reverse motion "
        "%.0f, rest of the\n"
        "  loop %.0f, element set-up, resultants to nodal loads and forward rotation %.0f, "
        "curvature matrices at the\n"
        "  3 corners DKT %.0f + 3 x %.0f (BCIZ 3 x %.0f); per in-plane point %.0f;\n"
        "  per material point: %.0f + elastic %.0f, or J2 trial %.0f + return (%.0f + %.0f per "
        "Newton evaluation) x the\n"
        "  share of the points that yield (notes below); %d Newton evaluations on the plate "
        "(J2Return::evaluations\n"
        "  on the steady plate; ONE would count %.0f instead of %.0f per yielding point), %d "
        "assumed on the tube.\n"
        "  Whole step adds per element %.0f (+%.0f pressure), per particle %.0f (+%.0f contact "
        "work); the contact\n"
        "  search and multiplier sweeps are NOT counted.\n",
        cost::k_transcendental, cost::k_reverse_motion, cost::k_element_rest, cost::k_loads_element,
        cost::k_dkt_shape, cost::k_bending_dkt, cost::k_bending_bciz, cost::k_inplane_point,
        cost::k_material_point, cost::k_elastic_update, cost::k_j2_trial, cost::k_j2_return,
        cost::k_j2_newton_evaluation, cost::k_j2_newton_evaluations_plate,
        cost::k_j2_trial + cost::k_j2_return + cost::k_j2_newton_evaluation,
        cost::k_j2_trial + cost::k_j2_return +
            cost::k_j2_newton_evaluations_plate * cost::k_j2_newton_evaluation,
        cost::k_j2_newton_evaluations_tube, cost::k_step_flops_per_element,
        cost::k_step_pressure_flops_per_element, cost::k_step_flops_per_particle,
        cost::k_step_contact_flops_per_particle);
    std::printf(
        "  Bytes: compulsory traffic if every array streams once per step: per element %.0f, per "
        "particle %.0f\n"
        "  (gathered x_prev, x, dtheta, drill_axis counted once per particle), per material point "
        "%.0f (read + write of %zu B);\n"
        "  whole step adds per element %.0f (+%.0f pressure), per particle %.0f (+%.0f pressure, "
        "+%.0f contact).\n"
        "  Meshes that fit the caches move far less to memory: their %% STREAM is a rate of "
        "touching data, not DRAM use.\n",
        cost::k_element_loop_bytes_per_element, cost::k_element_loop_bytes_per_particle,
        cost::k_bytes_per_material_point, sizeof(MaterialPoint), cost::k_step_bytes_per_element,
        cost::k_step_pressure_bytes_per_element, cost::k_step_bytes_per_particle,
        cost::k_step_pressure_bytes_per_particle, cost::k_step_contact_bytes_per_particle);
    std::printf(
        "- %% FMA peak / %% STREAM are against the peak of the same thread count. Models under 2 "
        "000 elements (and\n"
        "  particles) run serially: their 'all threads' rows use one thread.\n"
        "- %% CPU: CPU time of the process / (threads x wall time) over the row's samples. Well "
        "under 100 %% on a\n"
        "  1-thread row means other processes took the core (the timing is contended); on an 'all "
        "threads' row it\n"
        "  also counts threads waiting idle (OpenMP spins for a while, then sleeps).\n");
    for (const std::string& n : notes) std::printf("- %s\n", n.c_str());
    std::printf("- total run time of the table: %.0f s\n", seconds(t_start, Clock::now()));
    return 0;
}

}  // namespace fpmshell::bench
