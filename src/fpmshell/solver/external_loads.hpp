// The external loads of the model at time t (theory.md §6.7): follower pressures on elements,
// forces and moments on nodes, each times its curve, air blasts on faces (§6.13); and the
// tangent-plane normals of the particles (§1.3), computed in the same pass because both come from
// the triangles' current cross products.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/boundary_conditions.hpp"
#include "fpmshell/solver/particle_state.hpp"

namespace fpmshell {

class ExternalLoads {
public:
    /// The model and its topology (each particle's triangles) must outlive the loads.
    ExternalLoads(const Model& model, const MeshTopology& topology);

    /// Whether a moment load exists (else s.m_ext stays zero and is neither written nor read).
    [[nodiscard]] bool has_moment_loads() const { return has_moment_loads_; }

    /// The tangent-plane normals and drill axes of the current positions s.x (§1.3, eq. 2.6c)
    /// and the external loads at time t into s.f_ext, s.m_ext; those of the previous call move
    /// to s.f_ext_prev, s.m_ext_prev (for the work of the step). parallel: particle loops in
    /// parallel (bitwise the same either way). A distributed run (`near`: the triangles
    /// around the held particles, `held`: those particles) computes only those.
    void set_subset(const std::vector<Index>* near, const std::vector<Index>* held);
    void update_normals_and_loads(ParticleState& s, const BoundaryConditions& bc, Real t,
                                  bool parallel);
    /// §7.6: the pressures and blasts on these eroded triangles stop (their faces are gone, as
    /// LS-DYNA drops the segment loads of deleted elements); the triangles still turn their
    /// particles' normals.
    void unload(const std::vector<Index>& eroded);

private:
    struct PressureGather {  ///< loaded particle -> its loaded triangles (CSR), in the load's order
        std::vector<Index> particle, begin, element;
    };
    /// §6.13 a blast: its faces' pulses, each triangle's face (-1: not loaded), the span of
    /// time in which some face is in its positive phase; scratch per face (padded to whole
    /// packs), from the pass of the cross products: side n.(c - x) and |n|^2 |c - x|^2 of its
    /// current normal n (the cross product) and centroid x, c the charge
    struct Blast {
        BlastFaces faces;
        std::vector<Index> face_of_element;
        Real first_arrival = 0, last_end = 0;
        std::vector<Real> dot, norms;
        bool active = false;    ///< at this step: inside its span
        bool in_order = false;  ///< its faces are every triangle in order (face k = triangle k)
        bool zeroed = false;    ///< its triangles' scales are zero (outside its span)
        /// with a subset: the packs of k_lanes faces that hold one of its triangles
        /// (ascending); the others' pulses are not evaluated here
        std::vector<Index> near_packs;
    };
    /// -p / 6 of the blasts on each of their triangles at time t (element_blast_scale_), from
    /// the current cross products and centroids: f_i = that times the cross product at each
    /// corner (as a pressure, §6.7); k_lanes faces at a time.
    void blast_scales(Real t, bool parallel);
    /// -p / 6 of faces first ... first + k_lanes - 1 of blast l from their dot and norms
    /// (Blast::dot, norms): the one evaluation of both passes (the same bits either way).
    [[nodiscard]] RealPack face_scales(std::size_t l, std::size_t first, const Real* dot,
                                       const Real* norms, Real t) const;
    /// The pass of the cross products (§1.3) of every triangle; with a single blast on every
    /// triangle in order and no subset, that blast's scales in the same pass, k_lanes
    /// triangles at a time (whether it did).
    bool cross_products(const ParticleState& s, Real t, bool parallel);

    const Model& model_;
    const MeshTopology& topology_;
    bool has_moment_loads_ = false;
    std::vector<PressureGather> pressure_gather_;  ///< per load (empty unless a pressure)
    std::vector<Blast> blasts_;                    ///< per model.blast_loads entry
    /// scratch: each triangle's blast_scale at the step, summed into the particles in the pass
    /// of the normals (empty without blasts)
    std::vector<Real> element_blast_scale_;
    std::vector<std::uint8_t> unloaded_;  ///< per triangle: eroded (empty: none)
    [[nodiscard]] bool loaded(Index e) const {
        return unloaded_.empty() || unloaded_[static_cast<std::size_t>(e)] == 0;
    }
    bool fused_pressure_ =
        false;  ///< load 0: a pressure on every triangle, summed with the normals
    std::vector<Vec3> element_cross_;           ///< scratch: (x2 - x1) x (x3 - x1) per triangle
    const std::vector<Index>* near_ = nullptr;  ///< set_subset (null: every triangle)
    const std::vector<Index>* held_ = nullptr;  ///< set_subset (null: every particle)
};

}  // namespace fpmshell
