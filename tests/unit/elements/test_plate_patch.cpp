// Patch tests on assembled meshes (benchmarks.md §1, theory.md §4.8), "form A": the exact
// field of a constant-strain / constant-curvature state is imposed on every node of a flat
// patch, and the assembled internal forces and moments at the interior nodes must vanish.
// - membrane (CST): passes on every mesh;
// - bending: DKT passes on every mesh; BCIZ passes only on meshes of three families of
//   parallel lines (squares cut by one diagonal) and misses on crossed-diagonal and perturbed
//   meshes (its known non-conformity). How far it misses is printed and bounded from below,
//   so a change that silently "fixes" or breaks the kernel shows up here.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/solver/shell_elements.hpp"

using namespace fpmshell;

namespace {

struct Patch {
    Model model;
    std::vector<bool> interior;
};

Patch patch(DiagonalPattern pattern, Real perturb, BendingKernel kernel,
            MembraneKernel membrane = MembraneKernel::Cst) {
    PlateParams pp;
    pp.nx = pp.ny = 4;
    pp.pattern = pattern;
    MeshData mesh = generate_plate(pp);
    Patch out;
    out.interior.assign(mesh.nodes.size(), true);
    for (Index p : mesh.node_sets.at("boundary")) out.interior[static_cast<std::size_t>(p)] = false;
    std::mt19937 rng(5);
    // perturb <= 0.04 of a unit square cut 4 x 4 keeps every triangle counter-clockwise.
    std::uniform_real_distribution<Real> u(-perturb, perturb);
    for (std::size_t p = 0; p < mesh.nodes.size(); ++p)
        if (out.interior[p]) mesh.nodes[p] += Vec3(u(rng), u(rng), 0);
    Model& m = out.model;
    m.nodes = mesh.nodes;
    m.triangles = mesh.triangles;
    m.materials.push_back({"m", "elastic", 1.0, 1.0e6, 0.3});
    m.sections.push_back({0, 0.01, 2, 3});
    m.element_section.assign(m.triangles.size(), 0);
    m.control.bending = kernel;
    m.control.membrane = membrane;
    return out;
}

/// Largest interior residual relative to the largest nodal load of the patch.
/// bending: w = 1/2 (a x^2 + b y^2) + c x y; membrane: u = G x.
Real interior_residual(const Patch& pt, bool bending) {
    const MeshTopology topology(pt.model);
    ShellElements el(pt.model, topology);
    ParticleState s;
    s.resize(pt.model.nodes.size());
    s.x_prev = pt.model.nodes;
    s.x = pt.model.nodes;
    const Real eps = 1e-7, a = 1.0, b = -0.6, c = 0.35;
    for (std::size_t p = 0; p < s.size(); ++p) {
        const Real x = s.x_prev[p].x(), y = s.x_prev[p].y();
        if (bending) {
            s.x[p].z() += eps * (0.5 * (a * x * x + b * y * y) + c * x * y);
            s.dtheta[p] = eps * Vec3(b * y + c * x, -(a * x + c * y), 0);  // (w,y, -w,x)
        } else {
            s.x[p] += eps * Vec3(0.8 * x + 0.3 * y, 0.3 * x - 0.5 * y, 0);
        }
    }
    el.compute(s, 0.0, 0.0);
    // Bending is judged on the moments and the transverse forces (the in-plane forces are
    // O(eps^2) membrane terms of the deflection, irrelevant here), each against its own scale.
    Real worst = 0;
    for (int kind = 0; kind < (bending ? 2 : 1); ++kind) {
        Real worst_interior = 0, scale = 0;
        for (std::size_t p = 0; p < s.size(); ++p) {
            const Real load = !bending    ? s.f_int[p].norm()
                              : kind == 0 ? s.m_int[p].norm()
                                          : std::abs(s.f_int[p].z());
            scale = std::max(scale, load);
            if (pt.interior[p]) worst_interior = std::max(worst_interior, load);
        }
        worst = std::max(worst, worst_interior / scale);
    }
    return worst;
}

}  // namespace

TEST(PatchTest, MembraneCstPassesOnEveryMesh) {
    for (auto pattern :
         {DiagonalPattern::Right, DiagonalPattern::Cross, DiagonalPattern::Alternate})
        for (Real perturb : {0.0, 0.04})
            // Exact in exact arithmetic; geometric terms of the reverse motion are O(eps) = 1e-7.
            EXPECT_LT(interior_residual(patch(pattern, perturb, BendingKernel::Bciz), false), 1e-6);
}

TEST(PatchTest, MembraneSmoothedPassesOnEveryMesh) {
    // Area-weighted side strains and the transposed force operator keep the patch test on
    // irregular meshes (equal weights would not: the areas of neighbours differ).
    for (auto pattern :
         {DiagonalPattern::Right, DiagonalPattern::Cross, DiagonalPattern::Alternate})
        for (Real perturb : {0.0, 0.04})
            EXPECT_LT(
                interior_residual(
                    patch(pattern, perturb, BendingKernel::Dkt, MembraneKernel::Smoothed), false),
                1e-6);  // O(eps) geometric terms only, as for the CST
}

TEST(PatchTest, DktBendingPassesOnEveryMesh) {
    for (auto pattern :
         {DiagonalPattern::Right, DiagonalPattern::Cross, DiagonalPattern::Alternate})
        for (Real perturb : {0.0, 0.04}) {
            const Real r = interior_residual(patch(pattern, perturb, BendingKernel::Dkt), true);
            std::printf("DKT  pattern %d perturb %.2f: interior residual %.2e\n",
                        static_cast<int>(pattern), perturb, r);
            EXPECT_LT(r, 1e-6);  // O(eps) geometric terms only
        }
}

TEST(PatchTest, BcizPassesOnlyOnThreeLineFamilyMeshes) {
    const Real regular =
        interior_residual(patch(DiagonalPattern::Right, 0.0, BendingKernel::Bciz), true);
    std::printf("BCIZ three line families: interior residual %.2e\n", regular);
    EXPECT_LT(regular, 1e-6);
    const Real crossed =
        interior_residual(patch(DiagonalPattern::Cross, 0.0, BendingKernel::Bciz), true);
    const Real perturbed =
        interior_residual(patch(DiagonalPattern::Right, 0.04, BendingKernel::Bciz), true);
    std::printf("BCIZ crossed diagonals: %.2e, perturbed: %.2e (theory.md §4.8: 3e-3 ... 1.4e-1)\n",
                crossed, perturbed);
    // The known miss (theory.md §4.8 table): well above round-off on both meshes.
    EXPECT_GT(crossed, 1e-3);
    EXPECT_GT(perturbed, 1e-3);
}
