// The bending step ratio is computed once per section and element shape class at set-up and
// shared (solver/element_time_steps.cpp): on a fine plate (h / L_c ~ 2.8, where the bending modes
// set the step) the critical step of every element must be what the element's own 9 x 9
// eigenproblem gives (theory.md §6.4), both on the regular mesh (few classes, shared) and on a
// jittered one (nearly every element its own class).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "fpmshell/elements/bending_time_step.hpp"
#include "fpmshell/elements/lumped_inertia.hpp"
#include "fpmshell/materials/elastic/linear_elastic.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/solver/shell_elements.hpp"

using namespace fpmshell;

namespace {

Model fine_plate(Index n, Real h, Real jitter) {
    PlateParams pp;
    pp.nx = pp.ny = n;
    pp.pattern = DiagonalPattern::Alternate;
    MeshData mesh = generate_plate(pp);
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> u(-1, 1);
    for (Vec3& x : mesh.nodes) x += jitter / static_cast<Real>(n) * Vec3(u(rng), u(rng), 0.0);
    Model m;
    m.nodes = mesh.nodes;
    m.triangles = mesh.triangles;
    m.materials.push_back({"steel", "elastic", 7800, 2.1e11, 0.3});
    m.sections.push_back({0, h, 2, 3});
    m.element_section.assign(m.triangles.size(), 0);
    m.control.bending = BendingKernel::Dkt;
    return m;
}

struct ElementSteps {
    Real membrane, own;  ///< L_c / c, and the step with the element's own bending eigenproblem
};

/// The critical step of element e by its own eigenproblem (§6.4), and its membrane step.
ElementSteps own_critical_dt(const Model& m, std::size_t e) {
    const Material& mat = m.materials[0];
    const Real h = m.sections[0].thickness;
    const Mat3 rigidity =
        LinearElastic(mat.youngs_modulus, mat.poisson_ratio).stiffness() * (h * h * h / 12.0);
    const Real c = std::sqrt(mat.youngs_modulus /
                             (mat.density * (1.0 - mat.poisson_ratio * mat.poisson_ratio)));
    const auto& t = m.triangles[e];
    const Vec3& p0 = m.nodes[static_cast<std::size_t>(t[0])];
    const Vec3& p1 = m.nodes[static_cast<std::size_t>(t[1])];
    const Vec3& p2 = m.nodes[static_cast<std::size_t>(t[2])];
    const Vec3 e1 = p1 - p0, d = p2 - p0;
    const Vec3 ex = e1.normalized();
    const TriangleShape shape(e1.norm(), d.dot(ex), ex.cross(d).norm());
    const Real two_area = e1.cross(d).norm();
    const Real lc =
        two_area /
        std::sqrt(std::max({e1.squaredNorm(), (p2 - p1).squaredNorm(), d.squaredNorm()}));
    const NodeInertiaShare share = lumped_node_share(mat.density, h, 0.5 * two_area);
    const Real membrane = lc / c;
    const Real bending = bending_critical_dt(BendingKernel::Dkt, shape, rigidity, share.mass,
                                             share.inertia, membrane);
    return {membrane, membrane * std::min(Real{1}, bending / membrane)};
}

}  // namespace

TEST(BendingRatioSharing, EveryElementKeepsTheStepOfItsOwnEigenproblem) {
    // 1 m plate, 40 x 40 cells, h = 0.05 m: L_c = 0.0177 m, h / L_c = 2.8
    for (Real jitter : {0.0, 0.2}) {
        SCOPED_TRACE(jitter);
        const Model m = fine_plate(40, 0.05, jitter);
        const MeshTopology topology(m);
        const ShellElements elements(m, topology);
        Real worst = 0;
        int bending_sets_step = 0;
        for (Index e = 0; e < elements.size(); ++e) {
            const ElementSteps own = own_critical_dt(m, static_cast<std::size_t>(e));
            worst = std::max(worst, std::abs(elements.critical_dt(e, m.nodes) - own.own) / own.own);
            bending_sets_step += own.own < 0.9 * own.membrane;
        }
        // a class spans local coordinates equal to 2^-32 relative: the step it shares is each
        // member's own to ~1e-9 (the eigenvalue is smooth in the coordinates)
        EXPECT_LT(worst, 1e-9);
        // and the bending modes do set the step of these elements
        EXPECT_EQ(bending_sets_step, elements.size());
    }
}
