// Dispatch of the run's calls to every observer, in the order they were added.
#include "fpmshell/driver/output_observer.hpp"

namespace fpmshell {

void ObserverList::load(RestartReader& restart) {
    for (OutputObserver* o : observers_) o->load(restart);
}

void ObserverList::start(const ExplicitSolver& solver) {
    for (OutputObserver* o : observers_) o->start(solver);
}

void ObserverList::sample(const ExplicitSolver& solver, Real time, std::optional<bool> converged) {
    for (OutputObserver* o : observers_) o->sample(solver, time, converged);
}

void ObserverList::frame(const ExplicitSolver& solver, Real time,
                         const std::vector<Vec3>& positions) {
    for (OutputObserver* o : observers_) o->frame(solver, time, positions);
}

void ObserverList::step_done(const ExplicitSolver& solver, const StepReport& report) {
    for (OutputObserver* o : observers_) o->step_done(solver, report);
}

void ObserverList::failure(const ExplicitSolver& solver, std::string_view error,
                           const std::vector<Vec3>& last_good_positions) {
    for (OutputObserver* o : observers_) o->failure(solver, error, last_good_positions);
}

void ObserverList::finish(const ExplicitSolver& solver, const RunEnd& end) {
    for (OutputObserver* o : observers_) o->finish(solver, end);
}

void ObserverList::flush() {
    for (OutputObserver* o : observers_) o->flush();
}

void ObserverList::save(RestartWriter& restart) const {
    for (const OutputObserver* o : observers_) o->save(restart);
}

}  // namespace fpmshell
