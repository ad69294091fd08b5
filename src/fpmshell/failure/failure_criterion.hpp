// A failure criterion as the rest of the code sees it (theory.md §7.6): its key under a
// plastic material's `failure`, the function that reads and checks its constants, and the
// object that judges a point after each step. Each criterion is a folder under failure/ that
// makes one FailureCriterion, and one line of failure_criteria.cpp lists it; any plastic law
// takes any of them.
#pragma once

#include <any>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

class YamlValue;
namespace deck {
class FailureCard;
}

/// A card of an LS-DYNA deck that adds this criterion to a material of the deck (a *MAT_ADD_
/// card): its keywords without `*` and `_TITLE`, and its translation
/// (io/lsdyna/deck_failure_card.hpp).
struct DeckFailureCard {
    std::vector<std::string> keywords;
    void (*translate)(deck::FailureCard& card) = nullptr;
};

/// What the criteria read of points after a step, m packs of k_lanes points each (a lane is
/// a point of some element: the elements of a SIMD block at one point, or the points of one
/// element; lanes of no point read zeros). The stress and plastic work only where some
/// criterion of the material reads_point().
struct FailurePacks {
    std::size_t m = 0;
    const RealPack* plastic_strain = nullptr;
    const RealPack* stress[3] = {nullptr, nullptr, nullptr};  ///< sxx, syy, sxy
    const RealPack* plastic_work = nullptr;
    /// the initial size of each lane's element, sqrt(2 A_0) (a square's side for either of its
    /// halves), for the criteria that regularize by it
    RealPack element_size = RealPack(0.0);
    /// t_n, the time of the state judged (the criteria that fail at a time)
    Real time = 0;
};

/// One criterion of one material, judging its points.
class PointFailure {
public:
    virtual ~PointFailure() = default;
    /// Numbers it keeps per point (its damage, ...), each 0 before the first step.
    [[nodiscard]] virtual std::size_t state_fields() const { return 0; }
    /// Whether it reads more of a point than its plastic strain.
    [[nodiscard]] virtual bool reads_point() const { return false; }
    static constexpr std::size_t k_no_field = static_cast<std::size_t>(-1);
    /// Where its damage fades the stress a point carries (eq. 7.6-6): the state number of the
    /// fading w the next step integrates (1 - w) sigma with, then the number of the w the last
    /// step did (written by the element); k_no_field: it does not fade.
    [[nodiscard]] virtual std::size_t fading_field() const { return k_no_field; }
    /// Brings its state of the points (state_fields() x in.m packs, [number][pack]) up to the
    /// step of duration dt, and adds to failed[j] the lanes of pack j that have failed; whether
    /// some lane has. A lane's result does not depend on the others', and judging a point
    /// twice after one step changes nothing.
    virtual bool judge(const FailurePacks& in, Real dt, RealPack* state,
                       MaskOf<RealPack>* failed) const = 0;
};

struct FailureCriterion {
    std::string name;  ///< its key under `failure`
    /// Reads its value under `failure` (checked) into its constants, for a material whose law
    /// and elastic constants are read.
    std::any (*read)(const YamlValue& value, const Material& material) = nullptr;
    /// The criterion of a material.
    std::unique_ptr<PointFailure> (*make)(const std::any& parameters,
                                          const Material& material) = nullptr;
    /// The deck cards that add it to a material (none: it is read from a material's own card
    /// or not from decks).
    std::vector<DeckFailureCard> deck_cards{};
};

/// Every criterion, in the order of failure_criteria.cpp.
[[nodiscard]] const std::vector<FailureCriterion>& failure_criteria();
/// The criterion of that name, nullptr if none.
[[nodiscard]] const FailureCriterion* find_failure_criterion(std::string_view name);

}  // namespace fpmshell
