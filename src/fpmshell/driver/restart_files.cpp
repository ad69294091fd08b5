// Restart file observer; the cadence and layout are in restart_files.hpp.
#include "fpmshell/driver/restart_files.hpp"

#include <fmt/format.h>

#include <exception>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include "fpmshell/core/communicator.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/io/run_directory.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

RestartFiles::RestartFiles(std::filesystem::path path, double every, const OutputSchedule& schedule,
                           OutputObserver& results)
    : path_(std::move(path)), every_(every), schedule_(schedule), results_(results) {}

void RestartFiles::start(const ExplicitSolver& /*solver*/) { last_write_ = Clock::now(); }

bool RestartFiles::clock_due(const StepReport& report) const {
    return every_ > 0 &&
           (std::chrono::duration<double>(Clock::now() - last_write_).count() >= every_ ||
            report.outcome == StepOutcome::Ends);
}

void RestartFiles::step_done(const ExplicitSolver& solver, const StepReport& report) {
    const bool due = report.restart_agreed
                         ? *report.restart_agreed
                         : clock_due(report) || report.outcome == StepOutcome::Pauses;
    if (due) write(solver, report.wall_seconds);
}

void RestartFiles::write(const ExplicitSolver& solver, double wall_seconds) {
    const Communicator& comm = Communicator::world();
    const bool in_pieces = comm.distributed();
    const std::filesystem::path dir = path_.parent_path();
    if (in_pieces) {
        // every rank its own particles and elements: no rank gathers the state
        std::string error;
        try {
            RestartWriter piece;
            solver.save_piece(piece);
            piece.save(dir / restart_piece_file(comm.rank(), solver.steps()));
        } catch (const std::exception& e) {
            error = e.what();
        }
        // every piece on disk (or one rank's failure known to all) before restart.bin names them
        if (comm.max(error.empty() ? 0L : 1L) != 0)
            throw std::runtime_error(
                error.empty() ? "another rank could not write its piece of the restart file"
                              : error);
    }
    if (comm.root()) {
        results_.flush();  // the files on disk hold at least what the restart file holds
        RestartWriter w;
        w.section("layout");
        w(in_pieces ? comm.size() : 0, solver.steps());
        solver.save(w, in_pieces);
        w.section("driver");
        w(schedule_, wall_seconds);
        results_.save(w);
        w.save(path_);
        // the pieces of the file just replaced (and of any file cut short) are stale now
        remove_restart_pieces_except(dir, in_pieces ? solver.steps() : -1);
    }
    last_write_ = Clock::now();
}

namespace {

/// Reads restart.bin's layout and loads the solver from it (and from its pieces).
void load_solver(RestartReader& r, ExplicitSolver& solver) {
    r.section("layout");
    int pieces = 0;
    long step = 0;
    r(pieces, step);
    if (pieces < 0 || step < 0) r.fail("restart file is damaged: its layout is not a layout");
    const std::filesystem::path dir = r.path().parent_path();
    solver.load(r, pieces, [&r, &dir, pieces, step](int rank) {
        const std::filesystem::path piece = dir / restart_piece_file(rank, step);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(piece, ec))
            r.fail(
                fmt::format("the piece {} of this restart file (written on {} ranks after "
                            "step {}) is missing; resume needs every piece",
                            piece.filename().string(), pieces, step));
        return RestartReader(piece);
    });
}

/// The solver (layout, solver sections) and the driver's section of restart.bin; returns the
/// wall seconds of the earlier segments.
double load_solver_and_schedule(RestartReader& r, ExplicitSolver& solver,
                                OutputSchedule& schedule) {
    load_solver(r, solver);
    r.section("driver");
    double wall_seconds = 0;
    r(schedule, wall_seconds);
    if (!schedule.fits_time(solver.time()))
        r.fail("restart file is damaged: its next output times do not fit its time");
    return wall_seconds;
}

}  // namespace

double RestartFiles::resume(const std::filesystem::path& path, ExplicitSolver& solver,
                            OutputSchedule& schedule, OutputObserver& results) {
    RestartReader r(path);
    const double wall_seconds = load_solver_and_schedule(r, solver, schedule);
    results.load(r);
    r.finish();
    return wall_seconds;
}

double RestartFiles::resume_solver(const std::filesystem::path& path, ExplicitSolver& solver,
                                   OutputSchedule& schedule) {
    RestartReader r(path);
    return load_solver_and_schedule(r, solver, schedule);
}

SeparationHistory RestartFiles::separation_history(const std::filesystem::path& path,
                                                   Index n_elements) {
    RestartReader r(path);
    r.section("layout");
    int pieces = 0;
    long step = 0;
    r(pieces, step);
    r.section("separation");
    SeparationHistory h;
    r(h.opened);
    r(h.splits);
    std::uint64_t before = 0;
    for (const std::uint64_t n : h.splits) {
        if (n < before || n > h.opened.size())
            r.fail("restart file is damaged: its separations do not fit its open sides");
        before = n;
    }
    for (const auto& [e, f] : h.opened)
        if (e < 0 || f <= e || f >= n_elements)
            r.fail(
                "restart file of another model or damaged: its open sides are not between "
                "two elements of this mesh");
    return h;
}

}  // namespace fpmshell
