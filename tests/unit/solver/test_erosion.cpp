// Failure and erosion (theory.md §7.6):
// - the erosion rule counts failed points as documented (one in-plane point's every point
//   through the thickness, or `points` of them anywhere, or the failed layers of
//   `layer_fraction`);
// - homogeneous paths (equibiaxial, plane strain, shear, uniaxial) erode every element once its
//   points reach the failure strain, within 1 % (the overshoot of one step), and the eroded
//   elements carry nothing after;
// - a plate torn in two along a weak band: the particles keep their mass bit for bit, the
//   energy balance closes to 1e-3 with the eroded internal energy, and the erosion adds nothing
//   to its error; the particles left with no element fly on unforced; 1 and 2 threads give
//   the same bits;
// - a rigid ball perforates a clamped plate (eroding contact): no NaN, the balance to 1e-3.
#include <gtest/gtest.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <cmath>
#include <functional>

#include "../eroding_band.hpp"
#include "../failure/homogeneous_paths.hpp"
#include "../one_section_model.hpp"
#include "fpmshell/failure/element_erosion.hpp"
#include "fpmshell/failure/plastic_strain/plastic_strain_failure.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {
namespace {

TEST(Erosion, TheRuleCountsTheFailedPointsAsDocumented) {
    Material m;
    add_plastic_strain_failure(m, 0.1);
    const ElementErosion one_station(m, 3, 2);  // 3 in-plane x 2 through the thickness
    // points 0-1 at in-plane point 0, 2-3 at 1, 4-5 at 2
    auto strains = [](std::vector<Real> a) {
        return [a](ElementFailurePoints& points) {
            for (std::size_t p = 0; p < a.size(); ++p)
                set_lane(points.plastic_strain[p / k_lanes], static_cast<int>(p % k_lanes), a[p]);
        };
    };
    EXPECT_FALSE(one_station.erodes(strains({0.2, 0, 0.2, 0, 0.2, 0}), 1, nullptr));  // one each
    EXPECT_TRUE(one_station.erodes(strains({0, 0, 0.1, 0.3, 0, 0}), 1, nullptr));     // station 1
    m.failure.points = 3;
    const ElementErosion three(m, 3, 2);
    EXPECT_TRUE(three.erodes(strains({0.2, 0, 0.2, 0, 0.2, 0}), 1, nullptr));
    EXPECT_FALSE(three.erodes(strains({0.2, 0, 0.2, 0, 0.05, 0}), 1, nullptr));
    // layer_fraction (LS-DYNA's NUMFIP < 0): 3 in-plane x 4 through (points 4g + k); a layer k
    // fails where one of its in-plane points has; half of 4 layers is 2
    m.failure.points = 0;
    m.failure.layer_fraction = 0.5;
    const ElementErosion half(m, 3, 4);
    auto layers = [&](std::vector<std::size_t> failed) {  // the failed points
        std::vector<Real> a(12, 0.0);
        for (const std::size_t p : failed) a[p] = 0.2;
        return half.erodes(strains(a), 1, nullptr);
    };
    EXPECT_TRUE(layers({0, 5}));      // layers 0 and 1, at different in-plane points
    EXPECT_FALSE(layers({0, 4, 8}));  // layer 0 alone, at every in-plane point
    EXPECT_FALSE(layers({3, 11}));    // layer 3 at two in-plane points: one layer
    m.failure.layer_fraction = 0.51;  // 2.04 layers: 3
    EXPECT_FALSE(ElementErosion(m, 3, 4).erodes(strains({0.2, 0.2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}),
                                                1, nullptr));
    EXPECT_TRUE(ElementErosion(m, 3, 4).erodes(strains({0.2, 0.2, 0, 0, 0, 0, 0.2, 0, 0, 0, 0, 0}),
                                               1, nullptr));
    m.failure.criteria.clear();  // cannot fail
    EXPECT_FALSE(ElementErosion(m, 3, 2).active());
}

TEST(Erosion, HomogeneousPathsErodeAtTheFailureStrain) {
    for (const test::HomogeneousPath& path : test::homogeneous_paths()) {
        SCOPED_TRACE(path.name);
        // failing at a plastic strain of 0.2
        const Model m =
            test::damaging_path(path.velocity, path.lateral_free, {"plastic_strain", Real{0.2}});
        ExplicitSolver s(m);
        Real alpha_before = 0, worst_error = 0;
        while (s.eroded_elements() == 0 && s.time() < 1) {
            alpha_before = s.elements().point_state(0, 0).plastic_strain;
            s.step(1e30);
            worst_error = std::max(worst_error, std::abs(s.energy().error()));
        }
        ASSERT_EQ(s.eroded_elements(), m.n_elements()) << "all at once: the path is homogeneous";
        const Real alpha = s.elements().point_state(0, 0).plastic_strain;
        EXPECT_LT(alpha_before, 0.2);
        EXPECT_GE(alpha, 0.2);
        EXPECT_LT(alpha, 0.2 * 1.01);  // one step's increment past it
        // the eroded elements carry nothing: no internal force on any particle after
        s.step(1e30);
        for (const Vec3& f : s.state().f_int) EXPECT_EQ(f, Vec3::Zero());
        EXPECT_LT(worst_error, 1e-3);
        EXPECT_LT(std::abs(s.energy().error()), 1e-3);
        // the strain work of the eroded elements left the internal energy for the eroded one
        EXPECT_GT(s.energy().eroded_internal, 0);
        EXPECT_LT(std::abs(s.energy().internal), 1e-9 * s.energy().eroded_internal);
    }
}

TEST(Erosion, ATornPlateKeepsItsMassAndItsEnergyBalance) {
    const Model m = test::eroding_band_plate(16);
    ExplicitSolver s(m);
    const std::vector<Real> mass = s.state().mass;
    Real worst = 0, before_erosion = 0;
    while (s.time() < m.control.end_time) {
        if (s.eroded_elements() == 0) before_erosion = s.energy().error();
        s.step(1e30);  // whole steps (a last step cut short to land on the end time moves the
                       // leapfrog's kinetic energy by 2e-4 of the balance, erosion or not)
        worst = std::max(worst, std::abs(s.energy().error()));
    }
    ASSERT_GT(s.eroded_elements(), 0);
    EXPECT_GT(s.first_erosion_time(), 1.0e-3);
    EXPECT_EQ(s.state().mass, mass);  // bit for bit: erosion removes no mass
    EXPECT_LT(worst, 1e-3);
    // erosion itself adds nothing to the balance: the eroded elements' work, their last half
    // step's included, is all booked (without that half step: 4e-4 more)
    EXPECT_LT(std::abs(s.energy().error() - before_erosion), 2e-5);
    // the particles all of whose elements have eroded fly on unforced
    std::vector<int> live(static_cast<std::size_t>(m.n_particles()), 0);
    for (Index e = 0; e < m.n_elements(); ++e)
        if (!s.elements().eroded(e))
            for (const Index p : m.triangles[static_cast<std::size_t>(e)])
                ++live[static_cast<std::size_t>(p)];
    std::vector<std::size_t> free_particles;
    for (std::size_t p = 0; p < live.size(); ++p)
        if (live[p] == 0) free_particles.push_back(p);
    ASSERT_FALSE(free_particles.empty());
    const std::vector<Vec3> v = s.state().v;
    for (int k = 0; k < 10; ++k) s.step(1e30);
    for (const std::size_t p : free_particles) EXPECT_EQ(s.state().v[p], v[p]);
}

TEST(Erosion, ThreadCountDoesNotChangeTheTornPlate) {
#ifdef _OPENMP
    for (const bool damage : {false, true}) {  // by plastic strain, by Johnson-Cook damage
        SCOPED_TRACE(damage);
        const Model m = test::eroding_band_plate(32, damage);  // 2048 elements: parallel
        auto run = [&](int threads) {
            omp_set_num_threads(threads);
            ExplicitSolver s(m);
            while (s.time() < 1.6e-3) s.step(1e30);
            return std::make_pair(s.state().x, s.eroded_elements());
        };
        const auto one = run(1), two = run(2);
        omp_set_num_threads(omp_get_num_procs());
        ASSERT_GT(one.second, 0);
        EXPECT_EQ(one.second, two.second);
        EXPECT_EQ(one.first, two.first);  // bitwise
    }
#else
    GTEST_SKIP() << "built without OpenMP";
#endif
}

TEST(Erosion, ABallPerforatesAClampedPlate) {
    // examples/plate_perforation: the ball at 200 m/s through a 2 mm plate failing at 0.25
    const Model m =
        read_model(std::string(FPMSHELL_SOURCE_DIR) + "/examples/plate_perforation/model.yaml");
    ExplicitSolver s(m);
    const std::vector<Real> mass = s.state().mass;
    Real worst = 0;
    while (s.time() < m.control.end_time) {
        s.step(1e30);
        worst = std::max(worst, std::abs(s.energy().error()));
    }
    EXPECT_GT(s.eroded_elements(), 10);
    for (const Vec3& x : s.state().x) ASSERT_TRUE(x.allFinite());
    EXPECT_EQ(s.state().mass, mass);
    EXPECT_LT(worst, 1e-3);
    // through the plate: the ball has lost some of its speed and goes on downwards, below it
    const RigidBodyState& ball = s.bodies()[0];
    EXPECT_LT(ball.v.z(), -150.0);
    EXPECT_GT(ball.v.z(), -199.0);
    EXPECT_LT(ball.u.z() + 0.0215, -0.03);  // its centre 3 cm below the plate
}

}  // namespace
}  // namespace fpmshell
