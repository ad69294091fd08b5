// Point masses (model-format.md `masses`, LS-DYNA's *ELEMENT_MASS and _NODE_SET; theory.md
// §6.1): each particle of a set gains `mass`, or the set's particles share `total` equally; the
// particles' masses are their elements' shares plus these, the solver moves them with it (a
// free plate pushed by a force: the momentum grows by the impulse, the centre of mass moves at
// F / M of the whole mass); a wrong entry is one InputError naming file, line and key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {
namespace {

/// A free elastic plate of 2 x 1 (4 x 2 squares, 15 particles), node sets by planes, with the
/// `masses` block `masses` (YAML lines), read from a file of the running test.
Model plate_with(const std::string& masses, const std::string& more = "") {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("fpmshell_point_masses_" + std::to_string(::getpid()) + "_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".yaml");
    std::ofstream(path) << "title: t\n"
                           "mesh: {generator: plate, length_x: 2, length_y: 1, nx: 4, ny: 2}\n"
                           "sets:\n"
                           "  left: {plane: {point: [0, 0, 0], normal: [1, 0, 0]}}\n"
                           "  right: {plane: {point: [2, 0, 0], normal: [1, 0, 0]}}\n"
                           "materials:\n"
                           "  steel: {type: elastic, density: 7800, youngs_modulus: 2.1e11, "
                           "poisson_ratio: 0.3}\n"
                           "sections:\n"
                           "  - {elements: all, material: steel, thickness: 0.01}\n"
                           "control:\n"
                           "  end_time: 1.0e-3\n" +
                               more + "masses:\n" + masses;
    Model m = read_model(path.string());
    std::filesystem::remove(path);
    return m;
}

Real sum(const std::vector<Real>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

}  // namespace

// `mass` on each particle of a set, `total` shared equally; the particle masses are the
// elements' shares plus them (2 x 1 x 0.01 x 7800 = 156 of plate).
TEST(PointMasses, AddToTheParticlesOfTheirSets) {
    const Model none = plate_with("  []\n");
    const Model m = plate_with("  - {nodes: left, mass: 2.5}\n  - {nodes: right, total: 6}\n");
    ASSERT_EQ(m.point_masses.size(), 2u);
    ASSERT_EQ(m.point_masses[0].nodes.size(), 3u);  // the plate's edge x = 0: 3 particles
    EXPECT_EQ(m.point_masses[0].masses, std::vector<Real>(3, 2.5));
    EXPECT_EQ(m.point_masses[1].masses, std::vector<Real>(3, 2.0));  // 6 over x = 2's 3
    const ExplicitSolver plain(none), massive(m);
    EXPECT_NEAR(sum(plain.state().mass), 156.0, 1e-9);
    EXPECT_NEAR(sum(massive.state().mass), 156.0 + 7.5 + 6.0, 1e-9);
    for (const Index p : m.point_masses[0].nodes)
        EXPECT_EQ(massive.state().mass[static_cast<std::size_t>(p)],
                  plain.state().mass[static_cast<std::size_t>(p)] + 2.5);
    // a point mass has no rotary inertia of its own
    EXPECT_EQ(massive.state().inertia, plain.state().inertia);
}

// A free plate pulled along x by 1 kN at its right edge, with and without 20 kg more on each
// particle of its left edge: the loads give both the impulse F t, so the momentum per time is
// the same while the heavier one's whole mass is 216 against 156.
TEST(PointMasses, TheWholeMassTakesTheLoad) {
    const std::string pull =
        "loads:\n  - {type: force, nodes: right, value: [333.3333333333333, 0, 0]}\n";
    const Model light_model = plate_with("  []\n", pull);
    const Model heavy_model = plate_with("  - {nodes: left, mass: 20}\n", pull);
    ExplicitSolver light(light_model), heavy(heavy_model);  // they keep the models
    const auto momentum = [](const ExplicitSolver& s) {
        Vec3 sum = Vec3::Zero();
        for (std::size_t p = 0; p < s.state().size(); ++p)
            sum += s.state().mass[p] * s.state().v[p];
        return sum;
    };
    for (int step = 0; step < 200; ++step) {
        light.step(1e30);
        heavy.step(1e30);
    }
    // each plate's steps follow its own deformation: the times are a few 1e-8 apart after 200
    // steps, and each impulse is the force times its own loaded steps
    const Vec3 p_light = momentum(light), p_heavy = momentum(heavy);
    EXPECT_GT(p_light.x(), 0.0);
    // (measured 1e-10 apart: the loaded steps span each run's time but for a step's rounding)
    EXPECT_NEAR(p_heavy.x() / heavy.time(), p_light.x() / light.time(),
                1e-8 * p_light.x() / light.time());
    EXPECT_NEAR(sum(heavy.state().mass) / sum(light.state().mass), 216.0 / 156.0, 1e-12);
}

// Masses spread by area (LS-DYNA's *ELEMENT_MASS_PART, and MAREA as a section's `area_mass`):
// a third of each element's share on each corner, so every particle gains the mass per area
// times a third of its triangles' area, and the whole mass is the total; `final` adds what the
// elements' own mass (156, with their area mass) leaves.
TEST(PointMasses, SpreadOnElementsByArea) {
    const Model none = plate_with("  []\n");
    const ExplicitSolver plain(none);
    const auto gained = [&](const Model& m) {
        const ExplicitSolver s(m);
        std::vector<Real> out(s.state().size());
        for (std::size_t p = 0; p < out.size(); ++p)
            out[p] = s.state().mass[p] - plain.state().mass[p];
        return out;
    };
    // the element shares of plain: rho h A / 3 per corner, so a mass per area q gives q / (rho h)
    // times the plain particle mass
    const Real rho_h = 7800 * 0.01;
    const Model total = plate_with("  - {elements: all, total: 8}\n");
    const std::vector<Real> by_total = gained(total);
    for (std::size_t p = 0; p < by_total.size(); ++p)
        EXPECT_NEAR(by_total[p], 4.0 / rho_h * plain.state().mass[p], 1e-12);
    EXPECT_NEAR(sum(by_total), 8.0, 1e-12);
    const Model final_mass = plate_with("  - {elements: all, final: 200}\n");
    EXPECT_NEAR(sum(gained(final_mass)), 44.0, 1e-9);
    // a section's area mass, 5 per unit area: 10 on the plate, counted as its own by `final`
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("fpmshell_area_mass_" + std::to_string(::getpid()) + ".yaml");
    std::ofstream(path) << "title: t\n"
                           "mesh: {generator: plate, length_x: 2, length_y: 1, nx: 4, ny: 2}\n"
                           "materials:\n"
                           "  steel: {type: elastic, density: 7800, youngs_modulus: 2.1e11, "
                           "poisson_ratio: 0.3}\n"
                           "sections:\n"
                           "  - {elements: all, material: steel, thickness: 0.01, area_mass: 5}\n"
                           "masses:\n"
                           "  - {elements: all, final: 200}\n"
                           "control:\n"
                           "  end_time: 1.0e-3\n";
    const Model nsm = read_model(path.string());
    std::filesystem::remove(path);
    const std::vector<Real> by_nsm = gained(nsm);
    EXPECT_NEAR(sum(by_nsm), 44.0, 1e-9);  // 10 of area mass, 34 more to reach 200
}

// Each mistake is one InputError naming the file, the line and the key.
TEST(PointMasses, AWrongEntryIsOneSentence) {
    for (const auto& [entry, words] : std::vector<std::pair<std::string, std::string>>{
             {"  - {nodes: left}\n", "exactly one of `mass`"},
             {"  - {nodes: left, mass: 1, total: 3}\n", "exactly one of `mass`"},
             {"  - {nodes: left, mass: -1}\n", "masses.0.mass"},
             {"  - {nodes: left, total: 0}\n", "masses.0.total"},
             {"  - {nodes: nowhere, mass: 1}\n", "masses.0.nodes"},
             {"  - {nodes: left, mass: 1, inertia: 2}\n", "inertia"},
             {"  - {nodes: left, elements: all, total: 1}\n", "exactly one of `nodes`"},
             {"  - {elements: all, mass: 1}\n", "exactly one of `total`"},
             {"  - {elements: all, final: 100}\n", "already weigh 156"}}) {
        try {
            (void)plate_with(entry);
            ADD_FAILURE() << entry << ": no error";
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(words), std::string::npos) << entry << ": " << what;
            EXPECT_NE(what.find(".yaml:"), std::string::npos) << what;
        }
    }
}

}  // namespace fpmshell
