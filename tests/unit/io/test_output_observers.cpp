// The result observers of a run (driver/output_observer.hpp), seen by a fake observer added
// through RunOptions::observers:
// - the list calls its observers in the order they were added;
// - a run to its end calls start, the samples and the frame at t = 0, then per step its
//   samples and frames at the step's time before step_done, the last step_done says Ends,
//   finish comes last with exit code 0; the samples and frames are the rows of history.csv and
//   the frames of fields.pvd;
// - a run stopped at a step says Pauses at that step; resumed, the observer is loaded before
//   start, gets no second t = 0 output, and continues from the next step;
// - a failed run calls failure once, with finite positions, after the last step_done and before
//   finish (exit code 1), and the failure frame is in fields.pvd.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fpmshell/driver/run_driver.hpp"
#include "fpmshell/io/csv_table.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "one_section_model.hpp"

namespace fpmshell {
namespace {

namespace fs = std::filesystem;

struct Call {
    std::string what;
    Real time = 0;
    StepOutcome outcome = StepOutcome::Continues;  ///< step_done
    int exit_code = 0;                             ///< finish
    bool finite = true;                            ///< failure: the positions it got
};

/// Records every call it receives.
class Recorder final : public OutputObserver {
public:
    std::vector<Call> calls;

    void load(RestartReader& /*restart*/) override { calls.push_back({"load"}); }
    void start(const ExplicitSolver& solver) override { calls.push_back({"start", solver.time()}); }
    void sample(const ExplicitSolver& /*solver*/, Real time,
                std::optional<bool> /*converged*/) override {
        calls.push_back({"sample", time});
    }
    void frame(const ExplicitSolver& /*solver*/, Real time,
               const std::vector<Vec3>& /*positions*/) override {
        calls.push_back({"frame", time});
    }
    void step_done(const ExplicitSolver& /*solver*/, const StepReport& report) override {
        calls.push_back({"step_done", report.time, report.outcome});
    }
    void failure(const ExplicitSolver& solver, std::string_view /*error*/,
                 const std::vector<Vec3>& positions) override {
        const bool finite = std::all_of(positions.begin(), positions.end(),
                                        [](const Vec3& x) { return x.allFinite(); });
        calls.push_back({"failure", solver.time(), StepOutcome::Continues, 0, finite});
    }
    void finish(const ExplicitSolver& solver, const RunEnd& end) override {
        calls.push_back({"finish", solver.time(), StepOutcome::Continues, end.exit_code});
    }

    [[nodiscard]] long count(const std::string& what) const {
        return std::count_if(calls.begin(), calls.end(),
                             [&](const Call& c) { return c.what == what; });
    }
};

/// A simply supported elastic plate, 4 x 4 squares, set vibrating by random initial
/// velocities, for about 40 steps: a history row every ~8 steps, a frame every ~20.
Model vibrating_plate(const fs::path& dir) {
    PlateParams pp;
    pp.nx = pp.ny = 4;
    pp.pattern = DiagonalPattern::Alternate;
    const MeshData mesh = generate_plate(pp);
    Model m = test::one_section_model(mesh, 0.01);
    m.title = "vibrating plate";
    m.source_file = (dir / "plate.yaml").string();
    BoundaryCondition bc;
    bc.nodes = m.node_sets.at("boundary");
    bc.fixed = {false, false, true, false, false, false};
    m.boundary.push_back(bc);
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(-1, 1);
    for (Index p = 0; p < m.n_particles(); ++p)
        m.initial_conditions.push_back({{p}, 0.1 * Vec3(u(rng), u(rng), u(rng)), Vec3::Zero()});
    m.control.end_time = 1;
    const Real dt = ExplicitSolver(m).stable_dt();
    m.control.end_time = 40 * dt;
    m.output.every = 8 * dt;
    m.output.fields_every = 20 * dt;
    HistoryRequest h;
    h.name = "centre_uz";
    h.nodes = {12};
    h.quantity = Quantity::Uz;
    m.output.histories.push_back(h);
    return m;
}

fs::path fresh_dir(const std::string& name) {
    const fs::path p = fs::temp_directory_path() /
                       ("fpmshell_observers_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

RunOptions quiet_run(const fs::path& dir, Recorder& recorder) {
    RunOptions o;
    o.output_dir = dir;
    o.echo = false;
    o.quiet = true;
    o.threads = 1;
    o.observers = {&recorder};
    return o;
}

long pvd_frames(const fs::path& dir) {
    std::ifstream in(dir / "fields.pvd");
    std::stringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    long n = 0;
    for (std::size_t at = text.find("<DataSet"); at != std::string::npos;
         at = text.find("<DataSet", at + 1))
        ++n;
    return n;
}

/// Checks the order of the calls after start: samples and frames of a step's time, then its
/// step_done (Continues but for the last); then, if `failed`, one failure; then finish.
void expect_steps_then_finish(const std::vector<Call>& calls, std::size_t first, bool failed) {
    ASSERT_LT(first, calls.size());
    std::size_t i = first;
    std::size_t last_step_done = 0;
    bool seen_frame = false;
    for (; i < calls.size() &&
           (calls[i].what == "sample" || calls[i].what == "frame" || calls[i].what == "step_done");
         ++i) {
        const Call& c = calls[i];
        if (c.what == "step_done") {
            last_step_done = i;
            seen_frame = false;
            continue;
        }
        // The outputs of a step come before its step_done, at its time, a sample before a frame.
        std::size_t next = i;
        while (next < calls.size() && calls[next].what != "step_done") ++next;
        ASSERT_LT(next, calls.size()) << "an output after the last step_done";
        EXPECT_EQ(c.time, calls[next].time) << c.what << " of another step, call " << i;
        if (c.what == "sample") {
            EXPECT_FALSE(seen_frame) << "a sample after the frame, call " << i;
        }
        seen_frame = seen_frame || c.what == "frame";
    }
    if (!failed) {
        ASSERT_GT(last_step_done, 0u);
    }
    for (std::size_t k = first; k < last_step_done; ++k)
        if (calls[k].what == "step_done") {
            EXPECT_EQ(calls[k].outcome, StepOutcome::Continues) << "call " << k;
        }
    if (failed) {
        ASSERT_LT(i, calls.size());
        EXPECT_EQ(calls[i].what, "failure");
        EXPECT_TRUE(calls[i].finite);
        ++i;
    }
    ASSERT_EQ(i + 1, calls.size()) << "calls after the steps: " << calls.size() - i;
    EXPECT_EQ(calls[i].what, "finish");
}

TEST(OutputObservers, TheListCallsItsObserversInTheOrderTheyWereAdded) {
    std::vector<int> order;
    struct Tagged final : OutputObserver {
        Tagged(std::vector<int>& order, int tag) : order_(order), tag_(tag) {}
        void flush() override { order_.push_back(tag_); }
        std::vector<int>& order_;
        int tag_;
    };
    Tagged outside(order, 2);
    ObserverList list;
    list.add<Tagged>(order, 1);
    list.attach(outside);
    list.add<Tagged>(order, 3);
    list.flush();
    list.flush();
    EXPECT_EQ(order, (std::vector<int>{1, 2, 3, 1, 2, 3}));
}

TEST(OutputObservers, ARunToItsEndCallsTheObserversInTheDocumentedOrder) {
    const fs::path dir = fresh_dir("end");
    const Model model = vibrating_plate(dir);
    Recorder recorder;
    ASSERT_EQ(run_model(model, quiet_run(dir / "out", recorder)), 0);
    const std::vector<Call>& calls = recorder.calls;
    ASSERT_GE(calls.size(), 5u);
    EXPECT_EQ(calls[0].what, "start");
    EXPECT_EQ(calls[1].what, "sample");
    EXPECT_EQ(calls[1].time, 0);
    EXPECT_EQ(calls[2].what, "frame");
    EXPECT_EQ(calls[2].time, 0);
    ASSERT_NO_FATAL_FAILURE(expect_steps_then_finish(calls, 3, false));
    const auto last_step = std::find_if(calls.rbegin(), calls.rend(),
                                        [](const Call& c) { return c.what == "step_done"; });
    EXPECT_EQ(last_step->outcome, StepOutcome::Ends);
    EXPECT_EQ(last_step->time, model.control.end_time);
    EXPECT_EQ(calls.back().exit_code, 0);
    EXPECT_EQ(recorder.count("load"), 0);
    EXPECT_GE(recorder.count("step_done"), 40);  // the step grows from a smaller first one
    EXPECT_EQ(recorder.count("sample"),
              static_cast<long>(CsvTable::read(dir / "out" / "history.csv").n_rows()));
    EXPECT_EQ(recorder.count("frame"), pvd_frames(dir / "out"));
    EXPECT_EQ(recorder.count("frame"), 3);  // t = 0, 20 dt, the end
    fs::remove_all(dir);
}

TEST(OutputObservers, AStoppedRunPausesAndItsResumptionIsLoadedBeforeStart) {
    const fs::path dir = fresh_dir("resume");
    const Model model = vibrating_plate(dir);
    Recorder first;
    RunOptions options = quiet_run(dir / "out", first);
    options.stop_at_step = 13;
    ASSERT_EQ(run_model(model, options), 0);
    ASSERT_NO_FATAL_FAILURE(expect_steps_then_finish(first.calls, 3, false));
    EXPECT_EQ(first.count("step_done"), 13);
    const auto paused = std::find_if(first.calls.rbegin(), first.calls.rend(),
                                     [](const Call& c) { return c.what == "step_done"; });
    EXPECT_EQ(paused->outcome, StepOutcome::Pauses);

    Recorder second;
    options = quiet_run(dir / "out", second);
    options.resume = true;
    ASSERT_EQ(run_model(model, options), 0);
    const std::vector<Call>& calls = second.calls;
    ASSERT_GE(calls.size(), 4u);
    EXPECT_EQ(calls[0].what, "load");
    EXPECT_EQ(calls[1].what, "start");
    EXPECT_EQ(calls[1].time, paused->time);
    ASSERT_NO_FATAL_FAILURE(expect_steps_then_finish(calls, 2, false));
    EXPECT_GT(calls[2].time, paused->time);
    EXPECT_EQ(first.count("sample") + second.count("sample"),
              static_cast<long>(CsvTable::read(dir / "out" / "history.csv").n_rows()));
    EXPECT_EQ(first.count("frame") + second.count("frame"), pvd_frames(dir / "out"));
    fs::remove_all(dir);
}

TEST(OutputObservers, AFailedRunCallsFailureOnceBeforeFinish) {
    const fs::path dir = fresh_dir("failure");
    Model model = vibrating_plate(dir);
    model.control.energy_error_limit = 1e-15;  // below round-off: the first steps exceed it
    Recorder recorder;
    ASSERT_EQ(run_model(model, quiet_run(dir / "out", recorder)), 1);
    ASSERT_NO_FATAL_FAILURE(expect_steps_then_finish(recorder.calls, 3, true));
    EXPECT_EQ(recorder.count("failure"), 1);
    EXPECT_EQ(recorder.calls.back().exit_code, 1);
    // The result files' frames and the last good state of the failure.
    EXPECT_EQ(pvd_frames(dir / "out"), recorder.count("frame") + 1);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace fpmshell
