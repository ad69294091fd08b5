// Progress of a run (model-format.md "Command line"): on a terminal, one line that updates in
// place (simulated time, step, dt, % done, wall time, estimated time left, energy error);
// with --quiet or when stdout is not a terminal, one plain line every ~5 % of end_time.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

class Progress {
public:
    /// Receives each plain progress line (without '\n'); for example LogFile::line, so that the
    /// lines also reach log.txt. Without a sink the lines go to stdout.
    using LineSink = std::function<void(const std::string&)>;

    /// `end_time`: simulated time at which the run ends (100 %). `quiet`: plain lines even on a
    /// terminal. `terminal`: overrides the isatty(stdout) test (for tests). The wall clock
    /// starts here.
    Progress(Real end_time, bool quiet, LineSink sink = {},
             std::optional<bool> terminal = std::nullopt);
    ~Progress();
    /// A resumed run starts at simulated time t0: the time left is estimated from the pace
    /// since then, not since t = 0.
    void resume_from(Real t0) { start_time_ = t0; }
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// Reports the state after a step. Cheap enough to call every step: the live line is
    /// redrawn at most 10 times a second; a plain line is printed each time `time` passes the
    /// next multiple of 5 % of end_time. `energy_error` is the ratio of model-format.md
    /// (printed in %).
    void update(Real time, long step, Real dt, Real energy_error);

    /// Ends the report: the live line is drawn a last time and closed with '\n'; in plain mode
    /// the last state is printed unless it was already. Calling it again does nothing.
    void finish();

    /// Erases the live line (terminal mode) so other output can start at column 0; the next
    /// update() draws it again. No effect in plain mode. LogFile calls it before echoing.
    void clear_line();

    [[nodiscard]] bool live() const { return live_; }

    /// The text of one progress line for the given state (no '\r' or '\n').
    [[nodiscard]] std::string line_text(Real time, long step, Real dt, Real energy_error,
                                        double wall_seconds) const;

private:
    using Clock = std::chrono::steady_clock;
    Real start_time_ = 0;  ///< simulated time at which this process started

    void draw_live();
    void emit_plain();
    [[nodiscard]] double elapsed() const;

    Real end_time_;
    bool live_;  ///< true: updating terminal line; false: plain lines
    LineSink sink_;
    Clock::time_point start_;
    Clock::time_point last_draw_{};
    bool drawn_ = false;  ///< a live line is on screen
    std::size_t drawn_width_ = 0;
    long next_mark_ = 1;  ///< next 5 % mark (1..20) for plain lines
    bool finished_ = false;
    bool have_state_ = false;
    bool state_printed_ = false;  ///< plain mode: the latest state has been printed
    Real time_ = 0;
    long step_ = 0;
    Real dt_ = 0;
    Real energy_error_ = 0;
};

}  // namespace fpmshell
