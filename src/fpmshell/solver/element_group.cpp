#include "fpmshell/solver/element_group.hpp"

#include <cmath>

#include "fpmshell/materials/material_law.hpp"

namespace fpmshell {

ElementGroup::ElementGroup(const Model& model, std::size_t section, const Mat3& stiffness,
                           Real youngs_modulus, Real poisson_ratio, std::size_t point_fields)
    : point_fields_(point_fields) {
    const Section& sec = model.sections[section];
    const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
    rule_.thickness = sec.thickness;
    rule_.inplane = triangle_rule(sec.inplane_points);
    switch (sec.thickness_rule) {
        case ThicknessRule::ByCount:
            rule_.through = thickness_rule(sec.thickness_points);
            break;
        case ThicknessRule::Gauss:
            rule_.through = gauss_thickness_rule(sec.thickness_points);
            break;
        case ThicknessRule::Lobatto:
            rule_.through = lobatto_thickness_rule(sec.thickness_points);
            break;
        case ThicknessRule::User:
            for (const auto& [zeta, weight] : sec.thickness_user_points)
                user_through_.push_back({zeta, weight});
            rule_.through = user_through_;
            break;
    }
    rule_.bending = model.control.bending;
    wave_speed_ = std::sqrt(youngs_modulus / (mat.density * (1.0 - poisson_ratio * poisson_ratio)));
    bending_rigidity_ = stiffness * (sec.thickness * sec.thickness * sec.thickness / 12.0);
    block_constants_.c11 = stiffness(0, 0);
    block_constants_.c12 = stiffness(0, 1);
    block_constants_.c33 = stiffness(2, 2);
    block_constants_.thickness_factor = (1.0 - 2.0 * poisson_ratio) / youngs_modulus;  // §3.4
    block_constants_.inplane = rule_.inplane;
    block_constants_.through = rule_.through;
    block_constants_.bending = rule_.bending;
}

void ElementGroup::allocate(std::size_t n_blocks, std::size_t n_alone, const KeptPlaces* blocks,
                            const KeptPlaces* alone) {
    const std::size_t n = n_points();
    block_store_ = blocks ? blocks->place : std::vector<std::size_t>{};
    alone_store_ = alone ? alone->place : std::vector<std::size_t>{};
    const std::size_t kept_blocks = blocks ? blocks->count : n_blocks;
    const std::size_t kept_alone = alone ? alone->count : n_alone;
    block_state_.assign(kept_blocks * block_size(), RealPack(0.0));
    alone_state_.assign(kept_alone * n * point_fields_, 0.0);
    for (std::size_t k = 0; k < point_fields_; ++k) {
        const Real v = initial_field(k);
        if (v == 0) continue;
        for (std::size_t b = 0; b < kept_blocks; ++b)
            for (std::size_t p = 0; p < n; ++p)
                block_state_[b * block_size() + k * n + p] = RealPack(v);
        for (std::size_t e = 0; e < kept_alone; ++e)
            for (std::size_t p = 0; p < n; ++p) alone_state_[(e * n + p) * point_fields_ + k] = v;
    }
}

std::unique_ptr<ElementGroup> make_element_group(const Model& model, std::size_t section) {
    const Material& mat =
        model.materials[static_cast<std::size_t>(model.sections[section].material)];
    return material_law(mat).make_group(model, section);
}

}  // namespace fpmshell
