// Time to read an LS-DYNA deck of n^2 shells (n = 1000: 10^6 quadrangles, 2 x 10^6 triangles,
// 106 MB in fixed columns, as a crash model's mesh is written) into fpmshell's model:
// - deck_translate: the keyword reader and the translation into the YAML model
//   (translate_lsdyna_deck);
// - deck_to_model: the whole read of `fpmshell run deck.k` before the solver is built
//   (read_lsdyna_deck: the translation, then the model reader, which reads the deck's mesh).
// The deck is written once into $TMPDIR (default /tmp), untimed, and removed at the end.
//   ./build/bench/fpmshell_bench --benchmark_filter=deck_
// The target: 10^6 elements read and translated in at most 3 s.
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "fpmshell/io/lsdyna_deck.hpp"

using namespace fpmshell;

namespace {

/// A deck of an n x n plate of quadrangles (a plastic section, a clamped edge), written once.
class PlateDeck {
public:
    explicit PlateDeck(long n) {
        const char* tmp = std::getenv("TMPDIR");
        path_ =
            (std::filesystem::path(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") /
             ("fpmshell_bench_deck_" + std::to_string(::getpid()) + "_" + std::to_string(n) + ".k"))
                .string();
        std::ofstream out(path_);
        out << "*KEYWORD\n*TITLE\nplate of " << n * n << " shells\n"
            << "*CONTROL_TERMINATION\n    1.0e-5\n*PART\nplate\n         1         1         1\n"
            << "*SECTION_SHELL\n         1         2    0.8333         5\n     0.001\n"
            << "*MAT_PIECEWISE_LINEAR_PLASTICITY\n"
            << "         1    7850.0   2.1e+11       0.3   2.5e+08   1.0e+09\n*NODE\n";
        std::string block;
        for (long j = 0; j <= n; ++j)
            for (long i = 0; i <= n; ++i)
                block += fmt::format("{:8d}{:16.9f}{:16.9f}{:16.9f}\n", j * (n + 1) + i + 1,
                                     0.001 * static_cast<double>(i), 0.001 * static_cast<double>(j),
                                     0.0);
        out << block << "*ELEMENT_SHELL\n";
        block.clear();
        for (long j = 0; j < n; ++j)
            for (long i = 0; i < n; ++i) {
                const long a = j * (n + 1) + i + 1;
                block += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", j * n + i + 1, 1, a, a + 1,
                                     a + n + 2, a + n + 1);
            }
        out << block << "*SET_NODE_LIST_GENERATE\n         1\n         1"
            << fmt::format("{:10d}", n + 1)
            << "\n*BOUNDARY_SPC_SET\n         1         0         1         1         1         1"
               "         1         1\n*END\n";
    }
    ~PlateDeck() { std::filesystem::remove(path_); }
    PlateDeck(const PlateDeck&) = delete;
    PlateDeck& operator=(const PlateDeck&) = delete;
    [[nodiscard]] const std::string& path() const { return path_; }

private:
    std::string path_;
};

void deck_translate(benchmark::State& state) {
    const PlateDeck deck(state.range(0));
    for (auto _ : state) {
        DeckTranslation t = translate_lsdyna_deck(deck.path(), deck.path());
        benchmark::DoNotOptimize(t.yaml.data());
    }
    state.counters["elements"] = static_cast<double>(state.range(0) * state.range(0));
}

void deck_to_model(benchmark::State& state) {
    const PlateDeck deck(state.range(0));
    for (auto _ : state) {
        Model m = read_lsdyna_deck(deck.path());
        benchmark::DoNotOptimize(m.nodes.data());
    }
    state.counters["elements"] = static_cast<double>(state.range(0) * state.range(0));
}

}  // namespace

BENCHMARK(deck_translate)->Arg(1000)->Unit(benchmark::kSecond)->Iterations(3);
BENCHMARK(deck_to_model)->Arg(1000)->Unit(benchmark::kSecond)->Iterations(3);
