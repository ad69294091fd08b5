// A material that exists only in this test, run by the element loop through the group
// mechanism (solver/element_group.hpp): an elastic-perfectly plastic von Mises material with
// a radial return and a point layout of its own (5 fields). The class below is all it needs
// here; the loop makes it a group through MaterialGroup<RadialReturnPlastic> and computes its
// elements one by one (it has no block path). In a model file it would also need its registry
// entry (materials/material_law.hpp; tests/material_law/ has a law that does).
//
// It must reproduce the linear elastic material while it does not yield, and hold the
// stress of a plate stretched far past yield on its yield surface.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "fpmshell/materials/elastic/linear_elastic.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/solver/shell_elements.hpp"
#include "one_section_model.hpp"

using namespace fpmshell;

namespace {

/// Elastic, perfectly plastic: the trial stress scaled back onto the von Mises surface of
/// radius yield_stress (a radial return, not the plane-stress closest point).
class RadialReturnPlastic {
public:
    RadialReturnPlastic(Real youngs_modulus, Real poisson_ratio, Real yield_stress)
        : elastic_(youngs_modulus, poisson_ratio), yield_(yield_stress) {}

    [[nodiscard]] const Mat3& stiffness() const { return elastic_.stiffness(); }
    [[nodiscard]] Real youngs_modulus() const { return elastic_.youngs_modulus(); }
    [[nodiscard]] Real poisson_ratio() const { return elastic_.poisson_ratio(); }

    // the point layout: stress 3, equivalent plastic strain, plastic work
    static constexpr std::size_t k_point_fields = 5;
    static constexpr bool k_stress_only = false;
    template <class Field>
    [[nodiscard]] MaterialPoint read_point(const Field& field) const {
        MaterialPoint mp;
        mp.stress = Voigt3(field(0), field(1), field(2));
        mp.plastic_strain = field(3);
        mp.plastic_work = field(4);
        return mp;
    }
    template <class Set>
    void write_point(const MaterialPoint& mp, const Set& set) const {
        for (std::size_t r = 0; r < 3; ++r) set(r, mp.stress(static_cast<Eigen::Index>(r)));
        set(3, mp.plastic_strain);
        set(4, mp.plastic_work);
    }
    [[nodiscard]] Real initial_field(std::size_t /*k*/) const { return 0; }

    /// old_state and new_state may be the same object.
    void update(const MaterialPoint& old_state, const Voigt3& d_eps, Real /*dt*/,
                MaterialPoint& new_state) const {
        const Voigt3 old_stress = old_state.stress;
        Voigt3 stress = old_stress + stiffness() * d_eps;
        Real alpha = old_state.plastic_strain, work = old_state.plastic_work;
        const Real vm = std::sqrt(stress(0) * stress(0) - stress(0) * stress(1) +
                                  stress(1) * stress(1) + 3.0 * stress(2) * stress(2));
        if (vm > yield_) {
            stress *= yield_ / vm;
            const Voigt3 d_eps_plastic = d_eps - stiffness().inverse() * (stress - old_stress);
            const Real d_work = 0.5 * (old_stress + stress).dot(d_eps_plastic);
            work += d_work;
            alpha += d_work / yield_;  // work-equivalent plastic strain
        }
        new_state.stress = stress;
        new_state.plastic_strain = alpha;
        new_state.plastic_work = work;
    }

private:
    LinearElastic elastic_;
    Real yield_;
};

constexpr Real k_youngs = 2.1e11, k_nu = 0.3, k_h = 0.01;

Model plate(MembraneKernel membrane) {
    PlateParams pp;
    pp.nx = 6;
    pp.ny = 4;
    pp.pattern = DiagonalPattern::Alternate;
    const MeshData mesh = generate_plate(pp);
    Model m = test::one_section_model(mesh, k_h, k_nu, k_youngs, 3, 3);
    m.control.bending = BendingKernel::Dkt;
    m.control.membrane = membrane;
    return m;
}

ElementGroupFactory radial_return(Real yield_stress) {
    return
        [yield_stress](const Model& model, std::size_t section) -> std::unique_ptr<ElementGroup> {
            return std::make_unique<MaterialGroup<RadialReturnPlastic>>(
                RadialReturnPlastic(k_youngs, k_nu, yield_stress), model, section);
        };
}

struct Result {
    std::vector<Vec3> force, moment;
    Real strain_work = 0, plastic_work = 0;
};

/// Stretches the plate by `stretch` in x and y, and bends it into a bump of height `bump`
/// (0: flat), in `steps` equal steps, through the element loop alone (no particle update).
Result deform(ShellElements& el, const Model& m, Real stretch, Real bump, int steps) {
    ParticleState s;
    s.resize(m.nodes.size());
    s.x = s.x_prev = m.nodes;
    Result r;
    for (int k = 1; k <= steps; ++k) {
        const Real f = static_cast<Real>(k) / steps;
        s.x_prev = s.x;
        for (std::size_t p = 0; p < m.nodes.size(); ++p) {
            const Vec3& x0 = m.nodes[p];
            s.x[p] = Vec3(x0.x() * (1 + f * stretch), x0.y() * (1 + f * stretch),
                          f * bump * std::sin(std::numbers::pi * x0.x()) *
                              std::sin(std::numbers::pi * x0.y()));
        }
        const ShellElements::StepTotals t = el.compute(s, 0, 1e-6);
        EXPECT_LT(t.failed_element, 0);
        r.strain_work += t.strain_work;
        r.plastic_work += t.plastic_work;
    }
    r.force = s.f_int;
    r.moment = s.m_int;
    return r;
}

/// The same deformation with the groups make_group makes.
Result deform(const Model& m, const ElementGroupFactory& make_group, Real stretch, Real bump,
              int steps) {
    const MeshTopology topology(m);
    ShellElements el(m, topology, make_group);
    return deform(el, m, stretch, bump, steps);
}

Real largest(const std::vector<Vec3>& v) {
    Real x = 0;
    for (const Vec3& a : v) x = std::max(x, a.cwiseAbs().maxCoeff());
    return x;
}

}  // namespace

TEST(MaterialGroup, ATestMaterialThatNeverYieldsIsLinearElastic) {
    constexpr Real never = std::numeric_limits<Real>::infinity();
    // Smoothed membrane: both materials go through the general element, the same operations.
    {
        const Model m = plate(MembraneKernel::Smoothed);
        const Result elastic = deform(m, make_element_group, 1e-3, 2e-3, 4);
        const Result test = deform(m, radial_return(never), 1e-3, 2e-3, 4);
        EXPECT_GT(largest(elastic.force), 0);
        EXPECT_GT(largest(elastic.moment), 0);
        for (std::size_t p = 0; p < m.nodes.size(); ++p) {
            EXPECT_EQ(test.force[p], elastic.force[p]) << p;
            EXPECT_EQ(test.moment[p], elastic.moment[p]) << p;
        }
        EXPECT_EQ(test.strain_work, elastic.strain_work);
        EXPECT_EQ(test.plastic_work, 0);
    }
    // CST membrane: the linear elastic elements go through the SIMD blocks, the test
    // material's through the general element: the same up to the rounding the block kernel is
    // allowed (1e-9 relative to the largest load, test_elastic_triangle_block.cpp).
    {
        const Model m = plate(MembraneKernel::Cst);
        const Result elastic = deform(m, make_element_group, 1e-3, 2e-3, 4);
        const Result test = deform(m, radial_return(never), 1e-3, 2e-3, 4);
        const Real f_scale = largest(elastic.force), m_scale = largest(elastic.moment);
        for (std::size_t p = 0; p < m.nodes.size(); ++p)
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(test.force[p](c), elastic.force[p](c), 1e-9 * f_scale) << p;
                EXPECT_NEAR(test.moment[p](c), elastic.moment[p](c), 1e-9 * m_scale) << p;
            }
        EXPECT_NEAR(test.strain_work, elastic.strain_work, 1e-9 * elastic.strain_work);
    }
}

TEST(MaterialGroup, ATestMaterialStretchedPastYieldStaysOnItsSurface) {
    // Equibiaxial stretch to 1 % in 20 steps of 5e-4, each twice the yield strain
    // eps_y = sigma_y (1 - nu) / E: every point is on its surface after the first step,
    // sigma_xx = sigma_yy = sigma_y, and every later strain increment is plastic. A step's
    // increment is measured on the configuration it starts from (§2), d eps_k = 5e-4 / (1 +
    // f_{k-1} 0.01); the first step's plastic work is the trapezoid of its stress, half of
    // sigma_y (d eps_1 - eps_y) per component. The rest is rounding (1e-9).
    constexpr int steps = 20;
    constexpr Real stretch = 0.01, eps_y = 2.5e-4;
    const Real yield_stress = eps_y * k_youngs / (1 - k_nu);
    Real alpha = 0,
         work = 0;  // the expected alpha, and plastic work per unit volume of the initial plate
    for (int k = 1; k <= steps; ++k) {
        const Real before = 1 + stretch * (k - 1) / steps;
        const Real d_eps = (stretch / steps) / before;
        const Real d_alpha =
            k == 1 ? d_eps - eps_y : 2 * d_eps;  // sigma_y d_alpha = the work of both components
        alpha += d_alpha;
        work += yield_stress * d_alpha * before * before;  // on the area the step starts from
    }
    const Model m = plate(MembraneKernel::Cst);
    const MeshTopology topology(m);
    ShellElements el(m, topology, radial_return(yield_stress));
    const Result r = deform(el, m, stretch, 0.0, steps);
    for (Index e = 0; e < el.size(); ++e) {
        const Voigt3 n = el.membrane_force(e) / k_h;
        EXPECT_NEAR(n(0), yield_stress, 1e-9 * yield_stress) << e;
        EXPECT_NEAR(n(1), yield_stress, 1e-9 * yield_stress) << e;
        EXPECT_NEAR(n(2), 0, 1e-9 * yield_stress) << e;
        for (int k = 0; k < el.thickness_points(e); ++k)
            EXPECT_NEAR(el.plastic_strain(e, k), alpha, 1e-9 * alpha) << e;
    }
    const Real initial_volume = 1.0 * 1.0 * k_h;
    EXPECT_NEAR(r.plastic_work, work * initial_volume, 1e-9 * r.plastic_work);
}
