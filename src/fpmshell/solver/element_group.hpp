// An element group: the elements of one section, the unit the element loop dispatches on (the
// element groups of OpenRadioss, the styles of LAMMPS). A group owns its material, its
// integration rule and the state of its material points, stored in the layout its material
// declares (k_point_fields numbers per point, materials/*.hpp):
//   - the elements of its SIMD blocks (k_lanes elements, one per lane) keep theirs block by
//     block, [field][point] as whole packs (solver/block_point_loads.hpp);
//   - the elements computed one by one keep theirs element by element, [point][field].
// A material with a block path (an overload of block_point_loads) has its elements computed
// k_lanes at a time; any other material, or any element outside the block kernel's bounds,
// goes through the general element shell_triangle_loads and the material's scalar update.
//
// A law's material is a class with the scalar update (update, stiffness, youngs_modulus,
// poisson_ratio) and its point layout (k_point_fields, k_stress_only, read_point, write_point,
// initial_field), made a group by MaterialGroup<Material> in its folder's make_group
// (materials/material_law.hpp). Its points are MaterialPoint (materials/material_point.hpp) or
// a type of its own, `Material::Point`, with a `stress` (Voigt3) and, where it has them, a
// `plastic_strain` and a `plastic_work`. Restart files and the transfer between ranks carry a
// point as its k_point_fields numbers, whatever they mean.
#pragma once

#include <array>
#include <concepts>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "fpmshell/core/kept_places.hpp"
#include "fpmshell/core/simd.hpp"
#include "fpmshell/elements/elastic_triangle_block.hpp"
#include "fpmshell/elements/shell_triangle.hpp"
#include "fpmshell/failure/element_erosion.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/block_point_loads.hpp"

namespace fpmshell {

/// Where an element's state lies in its group: lane index % k_lanes of the group's block
/// index / k_lanes, or the index-th of the group's elements computed alone.
struct GroupPlace {
    bool in_block = false;
    std::size_t index = 0;
};

/// The element loop's view of a group, whatever its material.
class ElementGroup {
public:
    virtual ~ElementGroup() = default;
    ElementGroup(const ElementGroup&) = delete;  // rule_.through may view user_through_
    ElementGroup& operator=(const ElementGroup&) = delete;

    [[nodiscard]] const ShellRule& rule() const { return rule_; }
    [[nodiscard]] std::size_t n_points() const {
        return static_cast<std::size_t>(rule_.n_points());
    }
    /// c = sqrt(E / rho (1 - nu^2)), the membrane wave speed (§6.4).
    [[nodiscard]] Real wave_speed() const { return wave_speed_; }
    /// D_b = (h^3 / 12) C (§4.1), for the bending critical step.
    [[nodiscard]] const Mat3& bending_rigidity() const { return bending_rigidity_; }
    /// The section's constants for the block kernel.
    [[nodiscard]] const ElasticSectionConstants& block_constants() const {
        return block_constants_;
    }
    /// Whether the material has a block path (its elements may be computed k_lanes at a time).
    [[nodiscard]] virtual bool has_block_path() const = 0;
    /// Whether a point's state is its stress only (restart files keep such points apart).
    [[nodiscard]] virtual bool stress_only() const = 0;

    /// Makes the state of n_blocks blocks and n_alone elements computed alone, at its
    /// initial values; with `blocks`, `alone` (of the group's) that of those kept alone (a rank
    /// of a distributed run keeps the state of the units it computes: the others' places must
    /// not be read).
    void allocate(std::size_t n_blocks, std::size_t n_alone, const KeptPlaces* blocks = nullptr,
                  const KeptPlaces* alone = nullptr);

    /// The numbers of state kept (of the points of the blocks and elements allocated).
    [[nodiscard]] std::size_t kept_numbers() const {
        return block_state_.size() * static_cast<std::size_t>(k_lanes) + alone_state_.size();
    }

    /// The loads of the k_lanes elements of the group's block b (lanes outside the block
    /// kernel's bounds are reported in `valid`, their state left as it was); fading: of the
    /// points' stress by their damage (eq. 7.6-6), nullptr where none fades.
    [[nodiscard]] virtual ElasticTriangleLoads<RealPack> block_loads(
        std::size_t b, const TriangleMotion<RealPack>& motion, const RealPack& thickness,
        Real viscous_rate, Real dt, const StressFading<RealPack>* fading) = 0;
    /// The loads of one element by the general element (shell_triangle.hpp; arguments as
    /// there), its points read from and written back to `place`.
    [[nodiscard]] virtual ShellTriangleLoads element_loads(
        GroupPlace place, const ReversedTriangle& rt, Real viscous_rate, Real dt, Real thickness,
        const Voigt3* smoothed_membrane, Real own_share, const StressFading<Real>* fading) = 0;
    /// The state of point p of the element at `place` as the output reads it (its stress, its
    /// plastic strain and work where the law has them).
    [[nodiscard]] virtual MaterialPoint point_state(GroupPlace place, std::size_t p) const = 0;
    /// Numbers per point of the state (the law's k_point_fields).
    [[nodiscard]] std::size_t point_fields() const { return point_fields_; }
    /// The state of point p of the element at `place` as its point_fields() numbers (restart
    /// files, the transfer between ranks), and its update from them.
    void read_fields(GroupPlace place, std::size_t p, Real* out) const {
        for (std::size_t k = 0; k < point_fields_; ++k) out[k] = field(place, p, k);
    }
    void write_fields(GroupPlace place, std::size_t p, const Real* in) {
        for (std::size_t k = 0; k < point_fields_; ++k) set_field(place, p, k, in[k]);
    }
    /// The equivalent plastic strain of point p of the element at `place` (output).
    [[nodiscard]] virtual Real plastic_strain(GroupPlace place, std::size_t p) const = 0;
    /// What the failure criteria read of every point of the element at `place` (§7.6): the
    /// plastic strain, and with `whole` the stress and plastic work too.
    virtual void failure_points(GroupPlace place, bool whole, ElementFailurePoints& out) const = 0;
    /// The same of the k_lanes elements of the group's block b, point by point as packs read in
    /// place (m = n_points()); m = 0 where the law's layout does not name those fields (then
    /// failure_points, element by element).
    [[nodiscard]] virtual FailurePacks block_failure_packs(std::size_t b) const = 0;

protected:
    ElementGroup(const Model& model, std::size_t section, const Mat3& stiffness,
                 Real youngs_modulus, Real poisson_ratio, std::size_t point_fields);
    /// The initial value of field k of a point.
    [[nodiscard]] virtual Real initial_field(std::size_t k) const = 0;
    /// Field k of point p of the element at `place`.
    [[nodiscard]] Real field(GroupPlace place, std::size_t p, std::size_t k) const {
        const std::size_t n = n_points();
        if (!place.in_block)
            return alone_state_[(stored_alone(place.index) * n + p) * point_fields_ + k];
        const auto w = static_cast<std::size_t>(k_lanes);
        return lane(block_state_const(place.index / w)[k * n + p],
                    static_cast<int>(place.index % w));
    }
    void set_field(GroupPlace place, std::size_t p, std::size_t k, Real v) {
        const std::size_t n = n_points();
        if (!place.in_block) {
            alone_state_[(stored_alone(place.index) * n + p) * point_fields_ + k] = v;
            return;
        }
        const auto w = static_cast<std::size_t>(k_lanes);
        set_lane(block_state(place.index / w)[k * n + p], static_cast<int>(place.index % w), v);
    }
    /// The state of the group's block b and of the next one kept (nullptr: b is the last).
    [[nodiscard]] RealPack* block_state(std::size_t b) {
        return block_state_.data() + stored_block(b) * block_size();
    }
    [[nodiscard]] const RealPack* block_state_const(std::size_t b) const {
        return block_state_.data() + stored_block(b) * block_size();
    }
    [[nodiscard]] const RealPack* next_block_state(std::size_t b) const {
        const std::size_t next = (stored_block(b) + 1) * block_size();
        return next < block_state_.size() ? block_state_.data() + next : nullptr;
    }

    ShellRule rule_;
    std::size_t point_fields_;
    /// a section's own rule through the thickness (model-format.md `thickness_rule` as a list),
    /// which rule_.through views; empty for the built-in rules
    std::vector<ThicknessPoint> user_through_;

private:
    [[nodiscard]] std::size_t block_size() const { return point_fields_ * n_points(); }
    /// Where the state of the group's block b, and of its element computed alone a, is kept.
    [[nodiscard]] std::size_t stored_block(std::size_t b) const {
        return block_store_.empty() ? b : block_store_[b];
    }
    [[nodiscard]] std::size_t stored_alone(std::size_t a) const {
        return alone_store_.empty() ? a : alone_store_[a];
    }

    Real wave_speed_ = 0;
    Mat3 bending_rigidity_ = Mat3::Zero();
    ElasticSectionConstants block_constants_;
    std::vector<RealPack> block_state_;  ///< [block kept][field][point]
    std::vector<Real> alone_state_;      ///< [element alone kept][point][field]
    /// per block, and per element alone, of the group: where its state is kept (empty: all
    /// kept, in order; KeptPlaces)
    std::vector<std::size_t> block_store_, alone_store_;
};

/// Whether Material has a block path.
template <class Material>
concept BlockMaterial = requires(const Material& m, const BlockStep& step) {
    { block_point_loads(m, step) } -> std::same_as<ElasticTriangleLoads<RealPack>>;
};

/// The point type of Material: its own Point, or MaterialPoint.
template <class Material>
struct PointOf {
    using type = MaterialPoint;
};
template <class Material>
requires requires { typename Material::Point; }
struct PointOf<Material> {
    using type = typename Material::Point;
};

/// The group of a section of Material.
template <class Material>
class MaterialGroup final : public ElementGroup {
public:
    using Point = typename PointOf<Material>::type;

    MaterialGroup(const Material& material, const Model& model, std::size_t section)
        : ElementGroup(model, section, material.stiffness(), material.youngs_modulus(),
                       material.poisson_ratio(), Material::k_point_fields),
          material_(material) {}

    [[nodiscard]] const Material& material() const { return material_; }
    [[nodiscard]] bool has_block_path() const override { return BlockMaterial<Material>; }
    [[nodiscard]] bool stress_only() const override { return Material::k_stress_only; }

    [[nodiscard]] ElasticTriangleLoads<RealPack> block_loads(
        std::size_t b, const TriangleMotion<RealPack>& motion, const RealPack& thickness,
        Real viscous_rate, Real dt,
        [[maybe_unused]] const StressFading<RealPack>* fading) override {
        if constexpr (BlockMaterial<Material>) {
            BlockStep step;
            step.motion = &motion;
            step.constants = &block_constants();
            step.thickness = thickness;
            step.state = block_state(b);
            step.n_points = n_points();
            step.next_state = next_block_state(b);
            step.viscous_rate = viscous_rate;
            step.dt = dt;
            step.fading = fading;
            return block_point_loads(material_, step);
        } else {
            throw std::logic_error("block step of a material without a block path");
        }
    }

    [[nodiscard]] ShellTriangleLoads element_loads(GroupPlace place, const ReversedTriangle& rt,
                                                   Real viscous_rate, Real dt, Real thickness,
                                                   const Voigt3* smoothed_membrane, Real own_share,
                                                   const StressFading<Real>* fading) override {
        std::array<Point, k_max_block_points> points;  // the largest rule of quadrature.hpp
        const std::span<Point> pts(points.data(), n_points());
        for (std::size_t p = 0; p < pts.size(); ++p) pts[p] = own_point(place, p);
        const ShellTriangleLoads loads =
            shell_triangle_loads<Material, Point>(rt, rule_, material_, pts, viscous_rate, dt,
                                                  thickness, smoothed_membrane, own_share, fading);
        for (std::size_t p = 0; p < pts.size(); ++p)
            material_.write_point(pts[p],
                                  [&](std::size_t k, Real v) { set_field(place, p, k, v); });
        return loads;
    }

    [[nodiscard]] MaterialPoint point_state(GroupPlace place, std::size_t p) const override {
        const Point own = own_point(place, p);
        if constexpr (std::is_same_v<Point, MaterialPoint>) {
            return own;
        } else {
            MaterialPoint mp;
            mp.stress = own.stress;
            if constexpr (requires { own.plastic_strain; }) mp.plastic_strain = own.plastic_strain;
            if constexpr (requires { own.plastic_work; }) mp.plastic_work = own.plastic_work;
            return mp;
        }
    }
    [[nodiscard]] Real plastic_strain(GroupPlace place, std::size_t p) const override {
        // a layout that names its plastic strain field: that field alone (the output reads it
        // for every point of every frame)
        if constexpr (requires { Material::k_plastic_strain; })
            return field(place, p, Material::k_plastic_strain);
        else
            return point_state(place, p).plastic_strain;
    }

    /// A layout that names its fields: the criteria read those alone, in place.
    static constexpr bool k_named_failure_fields = requires {
        Material::k_stress;
        Material::k_plastic_strain;
        Material::k_plastic_work;
    };
    void failure_points(GroupPlace place, bool whole, ElementFailurePoints& out) const override {
        for (std::size_t p = 0; p < n_points(); ++p) {
            const auto j = p / static_cast<std::size_t>(k_lanes);
            const auto l = static_cast<int>(p % static_cast<std::size_t>(k_lanes));
            if constexpr (k_named_failure_fields) {
                set_lane(out.plastic_strain[j], l, field(place, p, Material::k_plastic_strain));
                if (!whole) continue;
                for (std::size_t r = 0; r < 3; ++r)
                    set_lane(out.stress[r][j], l, field(place, p, Material::k_stress + r));
                set_lane(out.plastic_work[j], l, field(place, p, Material::k_plastic_work));
            } else {
                const MaterialPoint mp = point_state(place, p);
                set_lane(out.plastic_strain[j], l, mp.plastic_strain);
                for (int r = 0; r < 3; ++r)
                    set_lane(out.stress[static_cast<std::size_t>(r)][j], l, mp.stress(r));
                set_lane(out.plastic_work[j], l, mp.plastic_work);
            }
        }
    }
    [[nodiscard]] FailurePacks block_failure_packs(std::size_t b) const override {
        FailurePacks in;
        if constexpr (k_named_failure_fields) {
            const RealPack* state = block_state_const(b);
            const std::size_t n = n_points();
            in.m = n;
            in.plastic_strain = state + Material::k_plastic_strain * n;
            for (std::size_t r = 0; r < 3; ++r) in.stress[r] = state + (Material::k_stress + r) * n;
            in.plastic_work = state + Material::k_plastic_work * n;
        }
        return in;
    }

private:
    [[nodiscard]] Point own_point(GroupPlace place, std::size_t p) const {
        return material_.read_point([&](std::size_t k) { return field(place, p, k); });
    }
    [[nodiscard]] Real initial_field(std::size_t k) const override {
        return material_.initial_field(k);
    }

    Material material_;
};

/// Makes the group of a section of the model (one per section).
using ElementGroupFactory =
    std::function<std::unique_ptr<ElementGroup>(const Model& model, std::size_t section)>;

/// The group of a section, made by its material's law (materials/material_law.hpp).
[[nodiscard]] std::unique_ptr<ElementGroup> make_element_group(const Model& model,
                                                               std::size_t section);

}  // namespace fpmshell
