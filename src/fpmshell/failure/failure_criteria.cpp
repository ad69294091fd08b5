// The registry of failure criteria: one line per criterion folder (failure_criterion.hpp).
#include "fpmshell/failure/failure_criterion.hpp"
#include "fpmshell/failure/johnson_cook/johnson_cook_damage.hpp"
#include "fpmshell/failure/plastic_strain/plastic_strain_failure.hpp"
#include "fpmshell/failure/tabulated/tabulated_failure.hpp"
#include "fpmshell/failure/thresholds/thresholds_failure.hpp"

namespace fpmshell {

const std::vector<FailureCriterion>& failure_criteria() {
    static const std::vector<FailureCriterion> criteria = {
        plastic_strain_criterion(),  // failure/plastic_strain
        johnson_cook_criterion(),    // failure/johnson_cook
        tabulated_criterion(),       // failure/tabulated
        thresholds_criterion(),      // failure/thresholds
    };
    return criteria;
}

const FailureCriterion* find_failure_criterion(std::string_view name) {
    for (const FailureCriterion& c : failure_criteria())
        if (c.name == name) return &c;
    return nullptr;
}

}  // namespace fpmshell
