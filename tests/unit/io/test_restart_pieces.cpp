// The pieces of a distributed run's restart file (ExplicitSolver::save_piece; load with pieces;
// model-format.md "Restart files"), on one rank, where the one piece holds every particle and
// element (the mpi tests cut them over 2 and 3 ranks):
// - a solver loaded from a restart.bin without the particles' and elements' state and from the
//   piece that holds it continues bit for bit like one loaded from the whole file, amid erosion;
// - restart.bin in pieces holds none of that state (it is far smaller than the whole file);
// - a piece that leaves the elements out, or one of another step, is refused with an
//   InputError that names it;
// - a block the writer keeps in its own memory (put_block, how a piece holds its state) makes
//   the same file as the vector written in line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../eroding_band.hpp"
#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {
namespace {

namespace fs = std::filesystem;

struct PieceFiles {
    fs::path dir;
    PieceFiles()
        : dir(fs::temp_directory_path() / ("fpmshell_pieces_" + std::to_string(::getpid()))) {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~PieceFiles() { fs::remove_all(dir); }
    PieceFiles(const PieceFiles&) = delete;
    PieceFiles& operator=(const PieceFiles&) = delete;
};

/// The eroding band (eroding_band.hpp): its elements erode from step 185 on.
Model band() {
    Model model = test::eroding_band_plate(16);
    model.title = "eroding band";
    return model;
}

/// Loads `solver` from restart.bin in pieces in dir, its one piece the file `piece`.
void load_from_pieces(ExplicitSolver& solver, const fs::path& dir, const fs::path& piece) {
    RestartReader r(dir / "restart.bin");
    solver.load(r, 1, [&piece](int) { return RestartReader(piece); });
    r.finish();
}

TEST(RestartPieces, ASolverLoadedFromItsPiecesContinuesAsFromTheWholeFile) {
    const PieceFiles files;
    const Model model = band();
    ExplicitSolver original(model);
    while (original.steps() < 190) original.step(1e30);
    ASSERT_GT(original.eroded_elements(), 0) << "no element eroded: the state carries no erosion";
    RestartWriter whole, manifest, piece;
    original.save(whole);
    original.save(manifest, true);
    original.save_piece(piece);
    whole.save(files.dir / "whole.bin");
    manifest.save(files.dir / "restart.bin");
    piece.save(files.dir / "piece.bin");
    EXPECT_LT(10 * manifest.size(), whole.size());  // the state is in the piece

    ExplicitSolver from_whole(model), from_pieces(model);
    {
        RestartReader r(files.dir / "whole.bin");
        from_whole.load(r);
        r.finish();
    }
    load_from_pieces(from_pieces, files.dir, files.dir / "piece.bin");
    for (int k = 0; k < 30; ++k) {
        from_whole.step(1e30);
        from_pieces.step(1e30);
    }
    EXPECT_EQ(from_pieces.state().x, from_whole.state().x);
    EXPECT_EQ(from_pieces.state().v, from_whole.state().v);
    EXPECT_EQ(from_pieces.eroded_elements(), from_whole.eroded_elements());
    EXPECT_EQ(from_pieces.energy().internal, from_whole.energy().internal);
    EXPECT_EQ(from_pieces.energy().eroded_internal, from_whole.energy().eroded_internal);
    for (Index e = 0; e < model.n_elements(); ++e) {
        ASSERT_EQ(from_pieces.elements().plastic_strain(e, 0),
                  from_whole.elements().plastic_strain(e, 0))
            << "element " << e;
        ASSERT_EQ(from_pieces.elements().membrane_force(e), from_whole.elements().membrane_force(e))
            << "element " << e;
    }
}

TEST(RestartPieces, APieceWithoutTheElementsOrOfAnotherStepIsRefused) {
    const PieceFiles files;
    const Model model = band();
    ExplicitSolver original(model);
    for (int k = 0; k < 20; ++k) original.step(1e30);
    RestartWriter manifest, piece;
    original.save(manifest, true);
    original.save_piece(piece);
    manifest.save(files.dir / "restart.bin");
    piece.save(files.dir / "piece.bin");
    // the piece's own sections, to write altered copies
    int rank = -1, ranks = 0;
    long steps = 0;
    Real time = 0;
    std::vector<char> particles, elements;
    {
        RestartReader r(files.dir / "piece.bin");
        r.section("piece");
        r(rank, ranks, steps, time);
        r.section("particles");
        r(particles);
        r.section("elements");
        r(elements);
        r.finish();
    }
    EXPECT_EQ(rank, 0);
    EXPECT_EQ(ranks, 1);
    EXPECT_EQ(steps, 20);
    auto altered = [&](const char* name, long piece_steps, const std::vector<char>& element_bytes) {
        RestartWriter w;
        w.section("piece");
        w(rank, ranks, piece_steps, time);
        w.section("particles");
        w(particles);
        w.section("elements");
        w(element_bytes);
        w.save(files.dir / name);
        ExplicitSolver solver(model);
        try {
            load_from_pieces(solver, files.dir, files.dir / name);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string no_elements = altered("no_elements.bin", steps, {});
    EXPECT_NE(no_elements.find("restart.bin"), std::string::npos) << no_elements;
    EXPECT_NE(no_elements.find("its piece does not hold every particle and element of this mesh"),
              std::string::npos)
        << no_elements;
    const std::string later = altered("later.bin", steps + 1, elements);
    EXPECT_NE(later.find("later.bin"), std::string::npos) << later;
    EXPECT_NE(later.find("after step 21"), std::string::npos) << later;
    std::vector<char> cut(elements.begin(), elements.end() - 3);
    const std::string cut_short = altered("cut.bin", steps, cut);
    EXPECT_NE(cut_short.find("cut.bin"), std::string::npos) << cut_short;
    EXPECT_NE(cut_short.find("damaged"), std::string::npos) << cut_short;
    // the unaltered piece loads
    ExplicitSolver solver(model);
    EXPECT_NO_THROW(load_from_pieces(solver, files.dir, files.dir / "piece.bin"));
}

TEST(RestartPieces, ABlockKeptApartMakesTheSameFileAsTheVectorInLine) {
    const PieceFiles files;
    std::vector<char> big(100000), small{'a', 'b'};
    for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i * 7919 % 251);
    RestartWriter in_line, apart;
    for (RestartWriter* w : {&in_line, &apart}) {
        w->section("one");
        (*w)(Real(1.5), std::vector<Real>{2, 3});
    }
    in_line(big);
    apart.put_block(big);
    for (RestartWriter* w : {&in_line, &apart}) {
        w->section("two");
        (*w)(long(7));
    }
    in_line(small);
    apart.put_block(small);
    EXPECT_EQ(apart.size(), in_line.size());
    in_line.save(files.dir / "in_line.bin");
    apart.save(files.dir / "apart.bin");
    auto bytes_of = [](const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(bytes_of(files.dir / "apart.bin"), bytes_of(files.dir / "in_line.bin"));
    RestartReader r(files.dir / "apart.bin");  // its checksum holds
    r.section("one");
    Real a = 0;
    std::vector<Real> b;
    std::vector<char> c, e;
    long d = 0;
    r(a, b, c);
    r.section("two");
    r(d, e);
    r.finish();
    EXPECT_EQ(c, big);
    EXPECT_EQ(e, small);
    EXPECT_EQ(d, 7);
}

}  // namespace
}  // namespace fpmshell
