// When a run writes a history row and a field frame (model-format.md "Results in DIR"): at the
// first step at or past each multiple of output.every (every step when it is 0), at the first
// step at or past each multiple of output.fields_every, and at the last step.
#pragma once

#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct Model;

class OutputSchedule {
public:
    explicit OutputSchedule(const Model& model);

    /// True when a history row is due at time t (`last`: the last step of the run); moves the
    /// next row time past t.
    [[nodiscard]] bool row_due(Real t, bool last);
    /// True when a field frame is due at time t; moves the next frame time past t.
    [[nodiscard]] bool frame_due(Real t, bool last);

    /// Whether the next row and frame times fit a run at time t: finite, and fewer than a
    /// million intervals behind it (a restart file's times, which a damaged file could set to
    /// make row_due and frame_due loop for ever).
    [[nodiscard]] bool fits_time(Real t) const;

    /// The restart file holds the next row and frame times (a resumed run may have other
    /// intervals: the next times were set by the first segment's).
    template <class Archive>
    friend void transfer(Archive& archive, OutputSchedule& s) {
        archive(s.next_row_, s.next_frame_);
    }

private:
    Real every_;         ///< output.every; 0: a row every step
    Real fields_every_;  ///< output.fields_every, or end_time when it is 0
    Real next_row_;
    Real next_frame_;
};

}  // namespace fpmshell
