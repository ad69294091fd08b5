// Progress reporter; behaviour described in progress.hpp.
#include "fpmshell/io/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fpmshell {

namespace {

constexpr int k_marks = 20;               // plain lines every 100 / 20 = 5 %
constexpr double k_redraw_seconds = 0.1;  // live line: at most 10 redraws a second

std::string duration_text(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0) return "--";
    if (seconds < 60) return fmt::format("{:.1f}s", seconds);
    const long s = std::lround(seconds);
    if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
    return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
}

}  // namespace

Progress::Progress(Real end_time, bool quiet, LineSink sink, std::optional<bool> terminal)
    : end_time_(end_time),
      live_(!quiet && terminal.value_or(::isatty(::fileno(stdout)) == 1)),
      sink_(std::move(sink)),
      start_(Clock::now()) {}

Progress::~Progress() {
    // An exception may be unwinding: end the live line so the error starts on a fresh line.
    if (live_ && drawn_ && !finished_) {
        std::fputc('\n', stdout);
        std::fflush(stdout);
    }
}

double Progress::elapsed() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
}

std::string Progress::line_text(Real time, long step, Real dt, Real energy_error,
                                double wall_seconds) const {
    const double fraction = end_time_ > 0 ? std::clamp(time / end_time_, 0.0, 1.0) : 1.0;
    // Time left from the pace since this process started (at start_time_ for a resumed run).
    const double done = time - start_time_;
    const double left = done > 0 ? wall_seconds * std::max(0.0, end_time_ - time) / done : NAN;
    return fmt::format(
        "t {:.4e} / {:.4e} ({:5.1f} %)  step {}  dt {:.3e}  wall {}  left {}  "
        "energy error {:.3f} %",
        time, end_time_, 100 * fraction, step, dt, duration_text(wall_seconds), duration_text(left),
        100 * energy_error);
}

void Progress::update(Real time, long step, Real dt, Real energy_error) {
    if (finished_) return;
    time_ = time;
    step_ = step;
    dt_ = dt;
    energy_error_ = energy_error;
    have_state_ = true;
    state_printed_ = false;
    if (live_) {
        const auto now = Clock::now();
        if (!drawn_ ||
            std::chrono::duration<double>(now - last_draw_).count() >= k_redraw_seconds) {
            draw_live();
        }
        return;
    }
    const double fraction = end_time_ > 0 ? time / end_time_ : 1.0;
    if (fraction * k_marks >= static_cast<double>(next_mark_)) {
        emit_plain();
        // Skip the marks this step jumped over, so one big step prints one line.
        next_mark_ =
            std::max(next_mark_ + 1, static_cast<long>(std::floor(fraction * k_marks)) + 1);
    }
}

void Progress::draw_live() {
    const std::string text = line_text(time_, step_, dt_, energy_error_, elapsed());
    std::string out = "\r" + text;
    if (text.size() < drawn_width_) out.append(drawn_width_ - text.size(), ' ');
    std::fputs(out.c_str(), stdout);
    std::fflush(stdout);
    drawn_width_ = text.size();
    drawn_ = true;
    last_draw_ = Clock::now();
}

void Progress::emit_plain() {
    const std::string text = line_text(time_, step_, dt_, energy_error_, elapsed());
    if (sink_) {
        sink_(text);
    } else {
        std::fputs((text + "\n").c_str(), stdout);
        std::fflush(stdout);
    }
    state_printed_ = true;
}

void Progress::clear_line() {
    if (!live_ || !drawn_) return;
    std::string out = "\r";
    out.append(drawn_width_, ' ');
    out += '\r';
    std::fputs(out.c_str(), stdout);
    std::fflush(stdout);
    drawn_ = false;
    drawn_width_ = 0;
}

void Progress::finish() {
    if (finished_) return;
    if (live_) {
        if (have_state_) {
            draw_live();
            std::fputc('\n', stdout);
            std::fflush(stdout);
        }
    } else if (have_state_ && !state_printed_) {
        emit_plain();
    }
    finished_ = true;
}

}  // namespace fpmshell
