// Particle separation (model/particle_separation.hpp, theory.md §7.7) on plates of 4 x 4
// squares cut in two triangles each, diagonals alternating:
// - a cut across the plate splits each particle on it in two, one per side, and the plate in
//   two pieces; a cut that stops inside splits the particles up to the one before its tip,
//   which stays whole (its fan is cut once), and the plate stays one piece; two cuts crossing
//   at a particle split it in four;
// - the result depends on the set of open edges alone (order, repeats), and a second pass with
//   the same edges splits nothing more;
// - the mass is split exactly: the exact sum over the particles keeps its bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "fpmshell/core/exact_sum.hpp"
#include "fpmshell/elements/lumped_inertia.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/model/particle_separation.hpp"

using namespace fpmshell;

namespace {

/// A plate of nx x ny squares over lx x ly, diagonals alternating.
MeshData plate(Index nx = 4, Index ny = 4, Real lx = 1, Real ly = 1) {
    return generate_plate({lx, ly, nx, ny, Vec3::Zero(), DiagonalPattern::Alternate});
}

Index particle_at(const MeshData& m, Real x, Real y) {
    for (std::size_t p = 0; p < m.nodes.size(); ++p)
        if (std::abs(m.nodes[p].x() - x) < 1e-12 && std::abs(m.nodes[p].y() - y) < 1e-12)
            return static_cast<Index>(p);
    ADD_FAILURE() << "no particle at " << x << ", " << y;
    return -1;
}

/// The edges of the mesh along the straight line from (x0, y0) to (x1, y1) (axis-parallel).
std::vector<MeshEdge> edges_along(const MeshData& m, Real x0, Real y0, Real x1, Real y1) {
    std::vector<MeshEdge> out;
    const auto on = [&](Index p) {
        const Vec3& q = m.nodes[static_cast<std::size_t>(p)];
        return q.x() >= x0 - 1e-12 && q.x() <= x1 + 1e-12 && q.y() >= y0 - 1e-12 &&
               q.y() <= y1 + 1e-12;
    };
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const Index p = t[static_cast<std::size_t>(k)],
                        q = t[static_cast<std::size_t>((k + 1) % 3)];
            if (on(p) && on(q)) out.push_back(mesh_edge(p, q));
        }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

/// The pieces of a mesh: its triangles joined through shared particles.
std::size_t pieces(const std::vector<std::array<Index, 3>>& triangles, std::size_t n) {
    std::vector<std::size_t> root(n);
    std::iota(root.begin(), root.end(), std::size_t{0});
    const auto find = [&](std::size_t i) {
        while (root[i] != i) i = root[i] = root[root[i]];
        return i;
    };
    std::vector<std::uint8_t> used(n, 0);
    for (const auto& t : triangles)
        for (const Index p : t) {
            used[static_cast<std::size_t>(p)] = 1;
            root[find(static_cast<std::size_t>(p))] = find(static_cast<std::size_t>(t[0]));
        }
    std::size_t count = 0;
    for (std::size_t p = 0; p < n; ++p) count += used[p] && find(p) == p;
    return count;
}

Real centre_y(const MeshData& m, Index e) {
    Real y = 0;
    for (const Index p : m.triangles[static_cast<std::size_t>(e)])
        y += m.nodes[static_cast<std::size_t>(p)].y() / 3;
    return y;
}

}  // namespace

TEST(ParticleSeparation, ACutAcrossThePlateSplitsItInTwo) {
    const MeshData m = plate();
    const std::vector<MeshEdge> cut = edges_along(m, 0, 0.5, 1, 0.5);
    ASSERT_EQ(cut.size(), 4u);
    const Separation s = separate_along_edges(m.triangles, m.nodes.size(), cut);
    ASSERT_EQ(s.splits.size(), 5u);  // every particle on the line, the ends included
    ASSERT_EQ(s.parent_of_new.size(), 5u);
    EXPECT_EQ(pieces(m.triangles, m.nodes.size()), 1u);
    EXPECT_EQ(pieces(s.triangles, m.nodes.size() + 5), 2u);
    for (std::size_t k = 0; k < s.splits.size(); ++k) {
        const ParticleSplit& split = s.splits[k];
        EXPECT_NEAR(m.nodes[static_cast<std::size_t>(split.parent)].y(), 0.5, 1e-12);
        ASSERT_EQ(split.groups.size(), 2u);
        ASSERT_EQ(split.children.size(), 1u);
        EXPECT_EQ(split.children[0], static_cast<Index>(m.nodes.size() + k));  // in parent order
        EXPECT_EQ(s.parent_of_new[k], split.parent);
        // each group on one side; the parent keeps the group of its lowest element
        for (const auto& group : split.groups) {
            const bool above = centre_y(m, group.front()) > 0.5;
            for (const Index e : group) EXPECT_EQ(centre_y(m, e) > 0.5, above);
        }
        EXPECT_LT(split.groups[0].front(), split.groups[1].front());
        for (const Index e : split.groups[1]) {
            const auto& t = s.triangles[static_cast<std::size_t>(e)];
            EXPECT_NE(std::find(t.begin(), t.end(), split.children[0]), t.end());
            EXPECT_EQ(std::find(t.begin(), t.end(), split.parent), t.end());
        }
    }
    // the other elements' corners are as they were
    std::size_t changed = 0;
    for (std::size_t e = 0; e < m.triangles.size(); ++e)
        changed += s.triangles[e] != m.triangles[e];
    std::size_t renumbered = 0;
    for (const ParticleSplit& split : s.splits) renumbered += split.groups[1].size();
    EXPECT_LE(changed, renumbered);
}

TEST(ParticleSeparation, ACutThatStopsInsideLeavesItsTipWhole) {
    const MeshData m = plate();
    const std::vector<MeshEdge> cut = edges_along(m, 0, 0.5, 0.5, 0.5);
    const Separation s = separate_along_edges(m.triangles, m.nodes.size(), cut);
    std::vector<Index> split;
    for (const ParticleSplit& p : s.splits) split.push_back(p.parent);
    EXPECT_EQ(split, (std::vector<Index>{particle_at(m, 0, 0.5), particle_at(m, 0.25, 0.5)}));
    EXPECT_EQ(pieces(s.triangles, m.nodes.size() + s.parent_of_new.size()), 1u);
}

TEST(ParticleSeparation, TwoCutsCrossingSplitTheirParticleInFour) {
    const MeshData m = plate();
    std::vector<MeshEdge> cut = edges_along(m, 0, 0.5, 1, 0.5);
    const std::vector<MeshEdge> other = edges_along(m, 0.5, 0, 0.5, 1);
    cut.insert(cut.end(), other.begin(), other.end());
    const Separation s = separate_along_edges(m.triangles, m.nodes.size(), cut);
    const Index centre = particle_at(m, 0.5, 0.5);
    const auto it = std::find_if(s.splits.begin(), s.splits.end(),
                                 [&](const ParticleSplit& p) { return p.parent == centre; });
    ASSERT_NE(it, s.splits.end());
    EXPECT_EQ(it->groups.size(), 4u);
    EXPECT_EQ(pieces(s.triangles, m.nodes.size() + s.parent_of_new.size()), 4u);
}

TEST(ParticleSeparation, TheResultDependsOnTheSetOfOpenEdgesAlone) {
    const MeshData m = plate();
    const std::vector<MeshEdge> cut = edges_along(m, 0, 0.5, 0.75, 0.5);
    const Separation first = separate_along_edges(m.triangles, m.nodes.size(), cut);
    std::vector<MeshEdge> shuffled = cut;
    shuffled.insert(shuffled.end(), cut.begin(), cut.end());  // repeats
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
    const Separation second = separate_along_edges(m.triangles, m.nodes.size(), shuffled);
    EXPECT_EQ(first.triangles, second.triangles);
    EXPECT_EQ(first.parent_of_new, second.parent_of_new);
    // the split mesh with the same edges again: every fan is already apart
    const Separation again =
        separate_along_edges(first.triangles, m.nodes.size() + first.parent_of_new.size(), cut);
    EXPECT_TRUE(again.splits.empty());
    EXPECT_EQ(again.triangles, first.triangles);
}

// The masses lumped from the elements (rho h A / 3 per corner, §6.1), each split particle's
// mass cut into its groups' shares: the exact sum over the particles keeps its bits, and each
// part is its group's share to rounding.
TEST(ParticleSeparation, TheMassIsSplitExactly) {
    const MeshData m = plate(7, 5, 0.3, 0.17);
    const Real density = 7850, thickness = 0.0013;
    std::vector<Real> corner(m.triangles.size());
    std::vector<Real> mass(m.nodes.size(), 0.0);
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
        const auto& t = m.triangles[e];
        const Vec3& a = m.nodes[static_cast<std::size_t>(t[0])];
        const Real area = 0.5 * (m.nodes[static_cast<std::size_t>(t[1])] - a)
                                    .cross(m.nodes[static_cast<std::size_t>(t[2])] - a)
                                    .norm();
        corner[e] = lumped_node_share(density, thickness, area).mass;
        for (const Index p : t) mass[static_cast<std::size_t>(p)] += corner[e];
    }
    ExactSum before;
    for (const Real x : mass) before.add(x);
    std::vector<MeshEdge> cut = edges_along(m, 0, 0.068, 0.3, 0.068);
    const std::vector<MeshEdge> other = edges_along(m, 3 * 0.3 / 7, 0, 3 * 0.3 / 7, 0.17);
    cut.insert(cut.end(), other.begin(), other.end());
    const Separation s = separate_along_edges(m.triangles, m.nodes.size(), cut);
    ASSERT_GE(s.splits.size(), 10u);
    std::vector<Real> after = mass;
    after.resize(m.nodes.size() + s.parent_of_new.size(), 0.0);
    for (const ParticleSplit& split : s.splits) {
        std::vector<Real> shares;
        for (std::size_t g = 1; g < split.groups.size(); ++g) {
            Real share = 0;
            for (const Index e : split.groups[g]) share += corner[static_cast<std::size_t>(e)];
            shares.push_back(share);
        }
        const std::vector<Real> parts =
            split_exactly(mass[static_cast<std::size_t>(split.parent)], shares);
        after[static_cast<std::size_t>(split.parent)] = parts[0];
        for (std::size_t k = 0; k < split.children.size(); ++k) {
            after[static_cast<std::size_t>(split.children[k])] = parts[k + 1];
            EXPECT_NEAR(parts[k + 1], shares[k],
                        1e-15 * mass[static_cast<std::size_t>(split.parent)]);
        }
    }
    ExactSum total;
    for (const Real x : after) total.add(x);
    EXPECT_EQ(total.value(), before.value());
    // and the exact sum's rounding hides nothing: the parts of each split add up exactly
    for (const ParticleSplit& split : s.splits) {
        ExactSum parts;
        parts.add(after[static_cast<std::size_t>(split.parent)]);
        for (const Index c : split.children) parts.add(after[static_cast<std::size_t>(c)]);
        parts.add(-mass[static_cast<std::size_t>(split.parent)]);
        EXPECT_EQ(parts.value(), 0.0);
    }
}

// split_exactly on awkward numbers: a share above half the rest, one far below it, one larger
// than the rest (clamped), a zero.
TEST(ParticleSeparation, SplitExactlyCutsWithoutLoss) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(0.0, 1.0);
    for (int trial = 0; trial < 1000; ++trial) {
        const Real whole = 0.1 + u(rng);
        std::vector<Real> shares{whole * u(rng) * 0.7, whole * 1e-9 * u(rng), 0.0, whole * u(rng)};
        const std::vector<Real> parts = split_exactly(whole, shares);
        ExactSum sum;
        for (const Real p : parts) {
            EXPECT_GE(p, 0.0);
            sum.add(p);
        }
        sum.add(-whole);
        EXPECT_EQ(sum.value(), 0.0) << "trial " << trial;
        EXPECT_NEAR(parts[1], shares[0], 1e-15);
        EXPECT_NEAR(parts[2], shares[1], 1e-15);
        EXPECT_EQ(parts[3], 0.0);
    }
}
