#include "fpmshell/failure/element_erosion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fpmshell {

ElementErosion::ElementErosion(const Material& material, int n_inplane, int n_through)
    : separates_(material.failure.separates),
      minimum_step_(material.failure.minimum_time_step),
      points_(material.failure.points),
      n_inplane_(n_inplane),
      n_through_(n_through) {
    // |NUMFIP| per cent of the layers: the least whole number of layers that reaches it (the
    // fraction's rounding, 1e-9, left out: 50 % of 4 layers is 2)
    if (const Real f = material.failure.layer_fraction; f > 0)
        layers_ = std::max(1, static_cast<int>(std::ceil(f * n_through - 1e-9)));
    for (const FailureCriterionSpec& spec : material.failure.criteria) {
        const FailureCriterion* c = find_failure_criterion(spec.name);
        if (!c) throw std::logic_error("failure criterion '" + spec.name + "' of no kind");
        std::shared_ptr<const PointFailure> f = c->make(spec.parameters, material);
        offsets_.push_back(fields_);
        if (fading_field_ == PointFailure::k_no_field &&
            f->fading_field() != PointFailure::k_no_field)
            fading_field_ = fields_ + f->fading_field();
        fields_ += f->state_fields();
        reads_point_ = reads_point_ || f->reads_point();
        criteria_.push_back(std::move(f));
    }
}

void ElementErosion::judge_block(const FailurePacks& in, Real dt, RealPack* state,
                                 std::array<bool, k_lanes>& erodes) const {
    std::array<MaskOf<RealPack>, 7 * k_max_thickness_points> failed;
    for (std::size_t p = 0; p < in.m; ++p) failed[p] = MaskOf<RealPack>(false);
    erodes.fill(false);
    if (!judge(in, dt, state, failed.data())) return;
    for (int l = 0; l < k_lanes; ++l)
        erodes[static_cast<std::size_t>(l)] =
            counts([&](std::size_t p) { return lane(failed[p], l); });
}

}  // namespace fpmshell
