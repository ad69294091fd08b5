// The result files of a run as observers of the solver (model-format.md "Results in DIR"): the
// run driver advances the solver and tells the observers what happened; each observer writes
// one file or report from the const solver state. A new result format is one OutputObserver.
//
// The calls, in the order the driver makes them:
//   load       resumed runs only: the observer's part of restart.bin, before start
//   start      once, before the first step (the solver is set up, or restored)
//   sample     at each history row time, t = 0 of a fresh run included
//   frame      at each field frame time, t = 0 of a fresh run included (after that time's sample)
//   step_done  after every step (dynamic) or load level (relaxation), after its sample and frame
//   failure    once, when the run fails: the solver holds the failed state; the positions are
//              the last good ones
//   finish     once, at the end, whatever the outcome (after failure, if any)
// flush and save may be called by another observer (restart files) between start and finish.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

class ExplicitSolver;
class RestartReader;
class RestartWriter;

/// How the run goes on after a step.
enum class StepOutcome {
    Continues,
    Ends,    ///< the last step: end time reached, or the watched rigid body stopped
    Pauses,  ///< the last step of this segment, to be resumed: a signal or --stop-at-step
};

/// What the driver reports after a step or load level.
struct StepReport {
    Real time = 0;  ///< simulated time (relaxation: load parameter) after the step
    /// Relaxation: |out-of-balance| / |external + reactions| at the end of the load level.
    std::optional<Real> residual_ratio;
    StepOutcome outcome = StepOutcome::Continues;
    double wall_seconds = 0;  ///< wall time of the time loop so far, all segments of a run
    /// A distributed run: whether every rank writes its piece of the restart file after this
    /// step (agreed by the ranks; RestartFiles decides by itself when empty).
    std::optional<bool> restart_agreed;
};

/// How the run ended.
struct RunEnd {
    int exit_code = 0;        ///< as run_model returns it
    std::string reason;       ///< summary.json "exit_reason"
    std::string message;      ///< a log line on why the run stopped early; empty when it did not
    double wall_seconds = 0;  ///< wall time of the time loop, all segments of a run
    int threads = 1;
    int ranks = 1;  ///< processes of a distributed run (core/communicator.hpp)
};

class OutputObserver {
public:
    virtual ~OutputObserver() = default;

    virtual void load(RestartReader& /*restart*/) {}
    virtual void start(const ExplicitSolver& /*solver*/) {}
    /// `converged`: relaxation only, whether the load level converged (true at t = 0).
    virtual void sample(const ExplicitSolver& /*solver*/, Real /*time*/,
                        std::optional<bool> /*converged*/) {}
    /// `positions`: those the frame shows (the solver's own in a running run).
    virtual void frame(const ExplicitSolver& /*solver*/, Real /*time*/,
                       const std::vector<Vec3>& /*positions*/) {}
    virtual void step_done(const ExplicitSolver& /*solver*/, const StepReport& /*report*/) {}
    virtual void failure(const ExplicitSolver& /*solver*/, std::string_view /*error*/,
                         const std::vector<Vec3>& /*last_good_positions*/) {}
    virtual void finish(const ExplicitSolver& /*solver*/, const RunEnd& /*end*/) {}

    /// Writes everything held in memory to its file now.
    virtual void flush() {}
    /// Appends what a resumed run needs to restore this observer (its own named section).
    virtual void save(RestartWriter& /*restart*/) const {}
};

/// The observers of a run, called in the order they were added.
class ObserverList final : public OutputObserver {
public:
    /// Adds an observer the list owns; returns it, for the observers that read another one.
    template <class T, class... Args>
    T& add(Args&&... args) {
        auto observer = std::make_unique<T>(std::forward<Args>(args)...);
        T& added = *observer;
        owned_.push_back(std::move(observer));
        observers_.push_back(&added);
        return added;
    }
    /// Adds an observer that outlives the list.
    void attach(OutputObserver& observer) { observers_.push_back(&observer); }

    void load(RestartReader& restart) override;
    void start(const ExplicitSolver& solver) override;
    void sample(const ExplicitSolver& solver, Real time, std::optional<bool> converged) override;
    void frame(const ExplicitSolver& solver, Real time,
               const std::vector<Vec3>& positions) override;
    void step_done(const ExplicitSolver& solver, const StepReport& report) override;
    void failure(const ExplicitSolver& solver, std::string_view error,
                 const std::vector<Vec3>& last_good_positions) override;
    void finish(const ExplicitSolver& solver, const RunEnd& end) override;
    void flush() override;
    void save(RestartWriter& restart) const override;

private:
    std::vector<std::unique_ptr<OutputObserver>> owned_;
    std::vector<OutputObserver*> observers_;
};

}  // namespace fpmshell
