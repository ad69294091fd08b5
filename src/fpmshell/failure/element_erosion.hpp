// Erosion (theory.md §7.6): when an element of a section whose material can fail stops acting.
// Its failure criteria (failure/<criterion>/, failure_criteria.cpp) judge its points after each
// step, each keeping its own state per point; the rule counts the failed points: by default the
// element erodes once every point through the thickness at one of its in-plane points has
// failed (LS-DYNA's rule for its shells of one in-plane point), or, with `points: N` (LS-DYNA's
// NUMFIP), once N of its points have, or, with `layer_fraction: f` (LS-DYNA's NUMFIP < 0), once
// that fraction of its layers through the thickness has failed, a layer where one of its
// points has.
//
// The criteria run on packs: the k_lanes elements of a SIMD block point by point (their state
// kept [number][point] as packs, a lane per element), or the points of one element computed
// alone k_lanes at a time (its state [number][pack of points]).
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/elements/quadrature.hpp"
#include "fpmshell/failure/failure_criterion.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// What the criteria read of the points of one element, point by point (in-plane major), as
/// packs of k_lanes points; past the element's points, zeros.
struct ElementFailurePoints {
    static constexpr std::size_t k_max_packs =
        (7 * static_cast<std::size_t>(k_max_thickness_points) + k_lanes - 1) / k_lanes;
    std::array<RealPack, k_max_packs> plastic_strain, stress[3], plastic_work;
};

class ElementErosion {
public:
    /// The rule of a material (inactive where it cannot fail) on a rule of n_inplane x
    /// n_through points, in-plane major.
    ElementErosion(const Material& material, int n_inplane, int n_through);

    /// Whether its points can fail (some criterion judges them).
    [[nodiscard]] bool active() const { return !criteria_.empty(); }
    /// The material's step below which an element erodes whatever its points (`failure:
    /// {minimum_time_step}`, LS-DYNA's TDEL); 0: none.
    [[nodiscard]] Real minimum_step() const { return minimum_step_; }
    /// Whether a failed element opens an edge instead of eroding (`fracture: separate`, §7.7).
    [[nodiscard]] bool separates() const { return separates_; }
    /// Whether some criterion reads more of a point than its plastic strain.
    [[nodiscard]] bool reads_point() const { return reads_point_; }
    /// State numbers per point, all criteria's.
    [[nodiscard]] std::size_t fields() const { return fields_; }
    /// The state number of the first criterion's fading (PointFailure::fading_field) among a
    /// point's fields(), the next number its applied fading; PointFailure::k_no_field: none.
    [[nodiscard]] std::size_t fading_field() const { return fading_field_; }
    [[nodiscard]] std::size_t n_points() const {
        return static_cast<std::size_t>(n_inplane_ * n_through_);
    }
    /// Packs of points of an element computed alone.
    [[nodiscard]] std::size_t point_packs() const {
        return (n_points() + k_lanes - 1) / static_cast<std::size_t>(k_lanes);
    }
    /// The state packs of an element computed alone, and of a SIMD block.
    [[nodiscard]] std::size_t alone_state_packs() const { return fields_ * point_packs(); }
    [[nodiscard]] std::size_t block_state_packs() const { return fields_ * n_points(); }

    /// Whether an element computed alone erodes after its step of duration dt, its criteria's
    /// state (alone_state_packs()) brought up to it. fill(points) sets what they read of its
    /// points: the plastic strain, and the stress and plastic work where reads_point();
    /// element_size, time: its FailurePacks::element_size and time.
    template <class Fill>
    [[nodiscard]] bool erodes(const Fill& fill, Real dt, RealPack* state, Real element_size = 0,
                              Real time = 0) const {
        ElementFailurePoints points;
        const std::size_t m = point_packs();
        for (std::size_t j = 0; j < m; ++j)
            points.plastic_strain[j] = points.stress[0][j] = points.stress[1][j] =
                points.stress[2][j] = points.plastic_work[j] = RealPack(0.0);
        fill(points);
        FailurePacks in;
        in.m = m;
        in.plastic_strain = points.plastic_strain.data();
        for (std::size_t r = 0; r < 3; ++r) in.stress[r] = points.stress[r].data();
        in.plastic_work = points.plastic_work.data();
        in.element_size = RealPack(element_size);
        in.time = time;
        std::array<MaskOf<RealPack>, ElementFailurePoints::k_max_packs> failed;
        failed.fill(MaskOf<RealPack>(false));
        if (!judge(in, dt, state, failed.data())) return false;
        return counts([&](std::size_t p) {
            return lane(failed[p / k_lanes], static_cast<int>(p % k_lanes));
        });
    }
    /// Which of the k_lanes elements of a SIMD block erode after the step (erodes[l]), their
    /// criteria's state (block_state_packs()) brought up to it: `in` the points' packs, n_points()
    /// of them, a lane per element (and each lane's element size).
    void judge_block(const FailurePacks& in, Real dt, RealPack* state,
                     std::array<bool, k_lanes>& erodes) const;

private:
    /// Every criterion brought up to the step (none skipped: each keeps its own state).
    bool judge(const FailurePacks& in, Real dt, RealPack* state, MaskOf<RealPack>* failed) const {
        bool any = false;
        for (std::size_t c = 0; c < criteria_.size(); ++c)
            any = criteria_[c]->judge(in, dt, state + offsets_[c] * in.m, failed) || any;
        return any;
    }
    /// The rule on the failed points of one element (failed(p), in-plane major).
    template <class Failed>
    [[nodiscard]] bool counts(const Failed& failed) const {
        if (layers_ > 0) {  // the failed layers: one of whose points has failed
            int failed_layers = 0;
            for (int k = 0; k < n_through_; ++k)
                for (int g = 0; g < n_inplane_; ++g)
                    if (failed(static_cast<std::size_t>(g * n_through_ + k))) {
                        ++failed_layers;
                        break;
                    }
            return failed_layers >= layers_;
        }
        int total = 0;
        bool one_inplane_point = false;
        for (int g = 0; g < n_inplane_; ++g) {
            int failed_here = 0;
            for (int k = 0; k < n_through_; ++k)
                if (failed(static_cast<std::size_t>(g * n_through_ + k))) ++failed_here;
            total += failed_here;
            one_inplane_point = one_inplane_point || failed_here == n_through_;
        }
        return points_ == 0 ? one_inplane_point : total >= points_;
    }

    std::vector<std::shared_ptr<const PointFailure>> criteria_;
    std::vector<std::size_t> offsets_;  ///< of each criterion's first number within a point's
    std::size_t fields_ = 0;            ///< state numbers per point
    std::size_t fading_field_ = PointFailure::k_no_field;
    bool reads_point_ = false;
    bool separates_ = false;
    Real minimum_step_ = 0;
    int points_ = 0;  ///< failed points that erode it; 0: one in-plane point's every point
    int layers_ = 0;  ///< failed layers that erode it (layer_fraction of n_through_); 0: points_
    int n_inplane_ = 0, n_through_ = 0;
};

/// Whether some section of the model is of a material that can fail, or its elements erode
/// below a minimum step (control.minimum_time_step; its results then carry the erosion's
/// columns and fields).
[[nodiscard]] inline bool model_can_erode(const Model& model) {
    if (model.control.minimum_time_step.active() && model.control.minimum_time_step.erode)
        return true;
    for (const Section& sec : model.sections)
        if (model.materials[static_cast<std::size_t>(sec.material)].failure.active()) return true;
    return false;
}

}  // namespace fpmshell
