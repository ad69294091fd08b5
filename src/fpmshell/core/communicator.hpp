// The processes of a distributed run (MPI_COMM_WORLD) as the solver uses them: a few collective
// reductions that give every rank the same bits (a minimum with its index, exact sums), the
// exchange of agreed buffers between neighbouring ranks, and the gathering of bytes on rank 0.
// Built without MPI (FPMSHELL_HAVE_MPI undefined), or started without mpirun, it is one rank
// and every operation is the identity: the serial run takes the same code path.
#pragma once

#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "fpmshell/core/exact_sum.hpp"
#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// Whether this build can run on several MPI ranks.
[[nodiscard]] bool mpi_available();

class Communicator {
public:
    /// The world of this process: MPI_COMM_WORLD once an MpiSession has started MPI, else one
    /// rank.
    [[nodiscard]] static const Communicator& world();

    [[nodiscard]] int rank() const { return rank_; }
    [[nodiscard]] int size() const { return size_; }
    [[nodiscard]] bool root() const { return rank_ == 0; }
    [[nodiscard]] bool distributed() const { return size_ > 1; }

    /// The smallest value over the ranks and, among the ranks that hold it, the lowest index
    /// (NaN counts as smaller than any number, so that a NaN step is reported).
    [[nodiscard]] std::pair<Real, Index> min_loc(Real value, Index index) const;
    /// The largest value over the ranks.
    [[nodiscard]] long max(long value) const;
    /// The least over the ranks of each of `values` (every rank gets them; no value may be
    /// NaN).
    void min(std::span<Real> values) const;
    /// The exact sums over the ranks of each of `sums` (every rank gets the totals).
    void sum(std::span<ExactSum> sums) const;
    /// Messages in flight between start_exchange and wait.
    class Pending {
    public:
        Pending();
        ~Pending();
        Pending(Pending&&) noexcept;
        Pending& operator=(Pending&&) noexcept;
        [[nodiscard]] bool active() const;

    private:
        friend class Communicator;
        struct Requests;
        std::unique_ptr<Requests> requests_;
    };
    /// Starts sending send[k] to rank peers[k] and receiving recv[k] from it (non-blocking: the
    /// work between this and wait overlaps the messages); the sizes of recv[k] are agreed
    /// beforehand, and no buffer may be touched before wait.
    [[nodiscard]] Pending start_exchange(const std::vector<int>& peers,
                                         const std::vector<std::vector<Real>>& send,
                                         std::vector<std::vector<Real>>& recv) const;
    /// Waits for every message of `pending` (nothing if none).
    void wait(Pending& pending) const;
    /// Every rank's values on every rank, in rank order: all holds counts[r] values of rank
    /// r (the counts agreed beforehand; counts[rank()] == mine.size()).
    void allgather(const std::vector<Real>& mine, const std::vector<int>& counts,
                   std::vector<Real>& all) const;
    /// Every rank's `mine` on every rank, in rank order.
    [[nodiscard]] std::vector<int> allgather(int mine) const;
    /// Every rank's bytes on every rank, joined in rank order.
    [[nodiscard]] std::vector<char> allgather(const std::vector<char>& mine) const;
    /// Every rank's bytes on rank 0 (rank order, its own first); the others get nothing.
    [[nodiscard]] std::vector<std::vector<char>> gather(const std::vector<char>& mine) const;
    /// Stops every rank (an error that only some ranks met: the others would wait forever).
    [[noreturn]] void abort(int exit_code) const;

private:
    Communicator(int rank, int size) : rank_(rank), size_(size) {}
    friend class MpiSession;
    int rank_ = 0, size_ = 1;
};

/// MPI from construction to destruction (main): MPI_Init_thread with the main thread alone
/// calling MPI (OpenMP threads never do), then MPI_Finalize. Without MPI it does nothing.
class MpiSession {
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
};

}  // namespace fpmshell
