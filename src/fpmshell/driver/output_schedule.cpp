// Output times of a run; the rules are in output_schedule.hpp.
#include "fpmshell/driver/output_schedule.hpp"

#include <cmath>

#include "fpmshell/model/model.hpp"

namespace fpmshell {

// A time within 1e-12 relative of an output time counts as reaching it: the step sums that
// land on a multiple of the interval differ from it by rounding only.
OutputSchedule::OutputSchedule(const Model& model)
    : every_(model.output.every),
      fields_every_(model.output.fields_every > 0 ? model.output.fields_every
                                                  : model.control.end_time),
      next_row_(every_),
      next_frame_(fields_every_) {}

bool OutputSchedule::row_due(Real t, bool last) {
    if (!(every_ <= 0 || t >= next_row_ * (1 - 1e-12) || last)) return false;
    while (every_ > 0 && next_row_ <= t * (1 + 1e-12)) next_row_ += every_;
    return true;
}

bool OutputSchedule::frame_due(Real t, bool last) {
    if (!(t >= next_frame_ * (1 - 1e-12) || last)) return false;
    while (next_frame_ <= t * (1 + 1e-12)) next_frame_ += fields_every_;
    return true;
}

bool OutputSchedule::fits_time(Real t) const {
    constexpr Real k_most_intervals_behind = 1e6;
    auto fits = [t](Real next, Real interval) {
        return std::isfinite(next) &&
               (interval <= 0 || t - next <= k_most_intervals_behind * interval);
    };
    return std::isfinite(t) && fits(next_row_, every_) && fits(next_frame_, fields_every_);
}

}  // namespace fpmshell
