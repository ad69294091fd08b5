// Fracture by particle separation in the solver (theory.md §7.7), on a plate with an edge slit
// pulled apart (mode I):
// - the crack starts at the slit's tip and runs across the ligament, the plate ends in two
//   halves (and at most small fragments where the crack branched); the total mass keeps its bits,
//   the energy balance closes to 1e-3 (the separation itself books no work: eq. 7.7-2 moves the
//   parts with their parent, so the kinetic energy and the elements' strain energy stay);
// - a split conserves momentum and mass: each part moves with its parent, the parts' masses
//   add up to the parent's exactly;
// - a restart after two separations resumes bitwise from the mesh made again from its history
//   (and the mesh as read refuses the file);
// - 1 and 2 threads give the same bits.
#include <gtest/gtest.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "../one_section_model.hpp"
#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/exact_sum.hpp"
#include "fpmshell/failure/plastic_strain/plastic_strain_failure.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/model/mesh_pieces.hpp"
#include "fpmshell/solver/separating_step.hpp"

namespace fpmshell {
namespace {

/// A 1 m x 1.5 m steel plate (h = 1 cm, J2 with linear hardening, failing at a plastic strain of
/// 5 %, `fracture: separate`) of nx x 1.5 nx squares, held flat, with a slit from its edge x = 0
/// along y = 0.75 to x = 0.25 (the mesh separated along it), its edges y = 0 and y = 1.5 pulled
/// apart, their speed ramped to 5 m/s each over 2 ms (the grips far from the slit: closer, the
/// plate fails at them first).
Model slit_plate(Index nx) {
    PlateParams pp;
    pp.length_x = 1;
    pp.length_y = 1.5;
    pp.nx = nx;
    pp.ny = 3 * nx / 2;
    pp.pattern = DiagonalPattern::Alternate;
    Model m = test::one_section_model(generate_plate(pp), 0.01, 0.3, 2.1e11, 3);
    make_bilinear(m.materials[0], 2.5e8, 1.0e9);
    add_plastic_strain_failure(m.materials[0], 0.05);
    m.materials[0].failure.separates = true;
    BoundaryCondition flat;
    for (Index p = 0; p < m.n_particles(); ++p) flat.nodes.push_back(p);
    flat.fixed = {false, false, true, true, true, false};
    m.boundary.push_back(flat);
    m.curves.push_back({"ramp", {{0.0, 0.0}, {2e-3, 1.0}}});
    for (const Real side : {-1.0, 1.0}) {
        BoundaryCondition pulled;
        pulled.nodes = m.node_sets.at(side < 0 ? "ymin" : "ymax");
        pulled.prescribed = PrescribedKind::Velocity;
        pulled.value = Vec3(0, 5.0 * side, 0);
        pulled.curve = 0;
        pulled.components = {false, true, false};
        m.boundary.push_back(pulled);
    }
    std::vector<MeshEdge> slit;
    for (const auto& t : m.triangles)
        for (std::size_t i = 0; i < 3; ++i) {
            const Index a = t[i], b = t[(i + 1) % 3];
            const Vec3& xa = m.nodes[static_cast<std::size_t>(a)];
            const Vec3& xb = m.nodes[static_cast<std::size_t>(b)];
            if (std::abs(xa.y() - 0.75) < 1e-9 && std::abs(xb.y() - 0.75) < 1e-9 &&
                std::max(xa.x(), xb.x()) < 0.25 + 1e-9)
                slit.push_back(mesh_edge(a, b));
        }
    m = separated_model(m, separate_along_edges(m.triangles, m.nodes.size(), slit));
    m.control.end_time = 12.0e-3;
    return m;
}

/// The element counts of the pieces of a mesh (its triangles joined through shared particles),
/// largest first.
std::vector<int> pieces(const Model& m) {
    const std::vector<Index> piece = mesh_pieces(m.nodes.size(), m.triangles);
    std::map<Index, int> count;
    for (const auto& t : m.triangles) ++count[piece[static_cast<std::size_t>(t[0])]];
    std::vector<int> sizes;
    for (const auto& [root_particle, n] : count) sizes.push_back(n);
    std::sort(sizes.rbegin(), sizes.rend());
    return sizes;
}

Real total_mass(const ExplicitSolver& s) {
    ExactSum sum;
    for (const Real m : s.state().mass) sum.add(m);
    return sum.value();
}

Vec3 momentum(const ExplicitSolver& s) {
    Vec3 p = Vec3::Zero();
    for (std::size_t i = 0; i < s.state().size(); ++i) p += s.state().mass[i] * s.state().v[i];
    return p;
}

TEST(ParticleSeparationRun, TheSlitPlateTearsFromTheSlitsTip) {
    const Model m = slit_plate(24);
    auto solver = std::make_unique<ExplicitSolver>(m);
    std::unique_ptr<Model> separated;
    const Real mass = total_mass(*solver);
    int separations = 0;
    Real worst = 0;
    bool tip_opened = false;
    while (solver->time() < m.control.end_time) {
        if (separating_step(solver, separated, 1e30)) ++separations;
        worst = std::max(worst, std::abs(solver->energy().error()));
        for (const auto& [a, b] : solver->open_side_pairs()) {
            // a side at the slit's tip (0.25, 0.25): both elements have a corner there
            const auto at_tip = [&](Index e) {
                for (const Index p : m.triangles[static_cast<std::size_t>(e)])
                    if ((m.nodes[static_cast<std::size_t>(p)] - Vec3(0.25, 0.75, 0)).norm() < 1e-9)
                        return true;
                return false;
            };
            tip_opened = tip_opened || (at_tip(a) && at_tip(b));
        }
    }
    EXPECT_TRUE(tip_opened) << "the crack starts at the slit's tip";
    // it runs across the ligament: two pieces of about half the plate each (the crack keeps
    // within a few rows of the slit's line), and at most a few small fragments where it
    // branched (under 3 % of the elements)
    const std::vector<int> sizes = pieces(solver->model());
    ASSERT_GE(sizes.size(), 2u);
    EXPECT_GT(sizes[1], m.n_elements() * 2 / 5);
    EXPECT_LT(m.n_elements() - sizes[0] - sizes[1], m.n_elements() * 3 / 100);
    EXPECT_GT(separations, 0);
    EXPECT_GT(solver->split_particles(), 0);
    EXPECT_EQ(solver->model().n_particles(), m.n_particles() + solver->split_particles());
    EXPECT_EQ(total_mass(*solver), mass);  // bit for bit
    EXPECT_LT(worst, 1e-3);
}

TEST(ParticleSeparationRun, ASplitKeepsMassAndMomentum) {
    const Model m = slit_plate(24);
    auto solver = std::make_unique<ExplicitSolver>(m);
    while (solver->time() < m.control.end_time) {
        solver->step(1e30);
        const Separation* separation = solver->separation_due();
        if (!separation) continue;
        const Model next_model = separated_model(solver->model(), *separation);
        const Real mass = total_mass(*solver);
        const Vec3 p = momentum(*solver);
        const ExplicitSolver next(next_model, *solver, *separation);
        EXPECT_EQ(total_mass(next), mass);
        EXPECT_LT((momentum(next) - p).norm(), 1e-12 * mass * 10.0);  // rounding of the sums
        for (const ParticleSplit& split : separation->splits)
            for (const Index c : split.children) {
                const auto uc = static_cast<std::size_t>(c),
                           up = static_cast<std::size_t>(split.parent);
                EXPECT_EQ(next.state().v[uc], next.state().v[up]);
                EXPECT_EQ(next.state().x[uc], next.state().x[up]);
                EXPECT_GT(next.state().mass[uc], 0);
            }
        return;
    }
    FAIL() << "no separation";
}

TEST(ParticleSeparationRun, ARestartAfterSplitsResumesBitwise) {
    Model m = slit_plate(24);
    m.control.end_time = 7e-3;
    auto solver = std::make_unique<ExplicitSolver>(m);
    std::unique_ptr<Model> separated;
    while (solver->separation_history().splits.size() < 2 && solver->time() < m.control.end_time)
        separating_step(solver, separated, 1e30);
    ASSERT_EQ(solver->separation_history().splits.size(), 2u);
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        ("fpmshell_separation_restart_" + std::to_string(::getpid()) + ".bin");
    RestartWriter out;
    solver->save(out);
    out.save(file);
    // the resumed run: its mesh made again from the model as read and the file's history
    RestartReader in(file);
    const Model replayed = replay_separations(m, solver->separation_history());
    EXPECT_EQ(replayed.triangles, solver->model().triangles);
    EXPECT_EQ(replayed.nodes, solver->model().nodes);
    auto resumed = std::make_unique<ExplicitSolver>(replayed);
    resumed->load(in);
    std::filesystem::remove(file);
    std::unique_ptr<Model> separated_resumed;
    while (solver->time() < m.control.end_time) {
        separating_step(solver, separated, 1e30);
        separating_step(resumed, separated_resumed, 1e30);
    }
    EXPECT_GT(solver->separation_history().splits.size(), 2u) << "splits after the restart";
    EXPECT_EQ(resumed->split_particles(), solver->split_particles());
    EXPECT_EQ(resumed->state().x, solver->state().x);  // bitwise
    EXPECT_EQ(resumed->energy().error(), solver->energy().error());
    // the mesh as read cannot take the file
    RestartWriter again;
    solver->save(again);
    again.save(file);
    RestartReader wrong(file);
    ExplicitSolver as_read(m);
    EXPECT_THROW(as_read.load(wrong), InputError);
    std::filesystem::remove(file);
}

TEST(ParticleSeparationRun, ABallPerforatesAClampedPlateThatSeparates) {
    // examples/plate_perforation with fracture: separate: the ball at 200 m/s tears a hole
    // whose petals bend away (the plate's self-contact and the ball's contact rebuilt at every
    // separation)
    Model m =
        read_model(std::string(FPMSHELL_SOURCE_DIR) + "/examples/plate_perforation/model.yaml");
    m.materials[0].failure.separates = true;
    auto solver = std::make_unique<ExplicitSolver>(m);
    std::unique_ptr<Model> separated;
    const Real mass = total_mass(*solver);
    Real worst = 0;
    while (solver->time() < m.control.end_time) {
        separating_step(solver, separated, 1e30);
        worst = std::max(worst, std::abs(solver->energy().error()));
    }
    EXPECT_GT(solver->split_particles(), 4);
    EXPECT_EQ(solver->eroded_elements(), 0);
    for (const Vec3& x : solver->state().x) ASSERT_TRUE(x.allFinite());
    EXPECT_EQ(total_mass(*solver), mass);
    EXPECT_LT(worst, 1e-3);
    EXPECT_EQ(pieces(solver->model()).size(), 1u) << "the petals stay on the plate";
    const RigidBodyState& ball = solver->bodies()[0];
    EXPECT_LT(ball.v.z(), -150.0);
    EXPECT_GT(ball.v.z(), -199.0);
    EXPECT_LT(ball.u.z() + 0.0215, -0.03);  // through the plate, its centre 3 cm below it
    EXPECT_EQ(solver->contact_statistics()->initial_penetrations, 0);
}

TEST(ParticleSeparationRun, OneAndTwoThreadsGiveTheSameBits) {
#ifdef _OPENMP
    const Model m = slit_plate(24);
    auto run = [&](int threads) {
        omp_set_num_threads(threads);
        auto solver = std::make_unique<ExplicitSolver>(m);
        std::unique_ptr<Model> separated;
        while (solver->time() < 6e-3) separating_step(solver, separated, 1e30);
        return std::make_pair(solver->state().x, solver->split_particles());
    };
    const auto one = run(1), two = run(2);
    omp_set_num_threads(omp_get_num_procs());
    ASSERT_GT(one.second, 0);
    EXPECT_EQ(one.second, two.second);
    EXPECT_EQ(one.first, two.first);  // bitwise
#else
    GTEST_SKIP() << "built without OpenMP";
#endif
}

}  // namespace
}  // namespace fpmshell
