#include "fpmshell/core/communicator.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>

#ifdef FPMSHELL_HAVE_MPI
#include <mpi.h>
#endif

namespace fpmshell {

namespace {
Communicator* g_world = nullptr;  // set by MpiSession while MPI runs
}  // namespace

bool mpi_available() {
#ifdef FPMSHELL_HAVE_MPI
    return true;
#else
    return false;
#endif
}

const Communicator& Communicator::world() {
    static const Communicator serial(0, 1);
    return g_world ? *g_world : serial;
}

#ifdef FPMSHELL_HAVE_MPI

namespace {
/// A value and its index, as min_loc reduces them.
struct ValueIndex {
    double value;
    long index;
};
/// (value, index) pairs: the smaller value, then the lower index; NaN below every number.
void min_loc_op(void* in, void* inout, int* len, MPI_Datatype*) {
    auto* a = static_cast<ValueIndex*>(in);
    auto* b = static_cast<ValueIndex*>(inout);
    for (int i = 0; i < *len; ++i) {
        const bool a_nan = std::isnan(a[i].value), b_nan = std::isnan(b[i].value);
        const bool a_first = a_nan != b_nan
                                 ? a_nan
                                 : (a_nan || a[i].value == b[i].value ? a[i].index < b[i].index
                                                                      : a[i].value < b[i].value);
        if (a_first) b[i] = a[i];
    }
}
// made once by MpiSession: min_loc runs several times a step
MPI_Datatype g_value_index_type = MPI_DATATYPE_NULL;
MPI_Op g_min_loc_op = MPI_OP_NULL;
}  // namespace

std::pair<Real, Index> Communicator::min_loc(Real value, Index index) const {
    if (size_ == 1) return {value, index};
    const ValueIndex mine{value, index < 0 ? std::numeric_limits<long>::max() : index};
    ValueIndex all{};
    MPI_Allreduce(&mine, &all, 1, g_value_index_type, g_min_loc_op, MPI_COMM_WORLD);
    return {all.value, all.index == std::numeric_limits<long>::max()
                           ? Index{-1}
                           : static_cast<Index>(all.index)};
}

long Communicator::max(long value) const {
    if (size_ == 1) return value;
    long all = 0;
    MPI_Allreduce(&value, &all, 1, MPI_LONG, MPI_MAX, MPI_COMM_WORLD);
    return all;
}

void Communicator::min(std::span<Real> values) const {
    if (size_ == 1 || values.empty()) return;
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MIN,
                  MPI_COMM_WORLD);
}

void Communicator::sum(std::span<ExactSum> sums) const {
    if (size_ == 1 || sums.empty()) return;
    // the carried digits of every sum (each below 2^32 but the last), added digit by digit:
    // exact for up to 2^30 ranks; NaN and infinities as a flag and their IEEE sum
    constexpr std::size_t nd = ExactSum::k_digits;
    std::vector<std::int64_t> digits(sums.size() * nd), total(digits.size());
    std::vector<double> special(sums.size()), special_total(sums.size());
    std::vector<int> flag(sums.size()), flag_any(sums.size());
    for (std::size_t k = 0; k < sums.size(); ++k) {
        const ExactSum::Digits d = sums[k].digits();
        std::copy(d.begin(), d.end(), digits.begin() + static_cast<std::ptrdiff_t>(k * nd));
        special[k] = sums[k].has_special() ? sums[k].special() : 0.0;
        flag[k] = sums[k].has_special() ? 1 : 0;
    }
    MPI_Allreduce(digits.data(), total.data(), static_cast<int>(digits.size()), MPI_INT64_T,
                  MPI_SUM, MPI_COMM_WORLD);
    MPI_Allreduce(special.data(), special_total.data(), static_cast<int>(special.size()),
                  MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    MPI_Allreduce(flag.data(), flag_any.data(), static_cast<int>(flag.size()), MPI_INT, MPI_MAX,
                  MPI_COMM_WORLD);
    for (std::size_t k = 0; k < sums.size(); ++k) {
        ExactSum::Digits d;
        std::copy(total.begin() + static_cast<std::ptrdiff_t>(k * nd),
                  total.begin() + static_cast<std::ptrdiff_t>((k + 1) * nd), d.begin());
        sums[k] = ExactSum::from_digits(d, flag_any[k] != 0, special_total[k]);
    }
}

struct Communicator::Pending::Requests {
    std::vector<MPI_Request> list;
};

Communicator::Pending Communicator::start_exchange(const std::vector<int>& peers,
                                                   const std::vector<std::vector<Real>>& send,
                                                   std::vector<std::vector<Real>>& recv) const {
    Pending pending;
    if (size_ == 1 || peers.empty()) return pending;
    pending.requests_ = std::make_unique<Pending::Requests>();
    std::vector<MPI_Request>& requests = pending.requests_->list;
    requests.resize(2 * peers.size());
    for (std::size_t k = 0; k < peers.size(); ++k)
        MPI_Irecv(recv[k].data(), static_cast<int>(recv[k].size()), MPI_DOUBLE, peers[k], 0,
                  MPI_COMM_WORLD, &requests[k]);
    for (std::size_t k = 0; k < peers.size(); ++k)
        MPI_Isend(send[k].data(), static_cast<int>(send[k].size()), MPI_DOUBLE, peers[k], 0,
                  MPI_COMM_WORLD, &requests[peers.size() + k]);
    return pending;
}

void Communicator::wait(Pending& pending) const {
    if (!pending.requests_) return;
    std::vector<MPI_Request>& requests = pending.requests_->list;
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
    pending.requests_.reset();
}

void Communicator::allgather(const std::vector<Real>& mine, const std::vector<int>& counts,
                             std::vector<Real>& all) const {
    if (size_ == 1) {
        all = mine;
        return;
    }
    std::vector<int> displacements(counts.size(), 0);
    for (std::size_t r = 1; r < counts.size(); ++r)
        displacements[r] = displacements[r - 1] + counts[r - 1];
    all.resize(static_cast<std::size_t>(displacements.back() + counts.back()));
    MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(),
                   counts.data(), displacements.data(), MPI_DOUBLE, MPI_COMM_WORLD);
}

std::vector<int> Communicator::allgather(int mine) const {
    std::vector<int> all(static_cast<std::size_t>(size_), mine);
    if (size_ > 1) MPI_Allgather(&mine, 1, MPI_INT, all.data(), 1, MPI_INT, MPI_COMM_WORLD);
    return all;
}

std::vector<char> Communicator::allgather(const std::vector<char>& mine) const {
    if (size_ == 1) return mine;
    const std::vector<int> counts = allgather(static_cast<int>(mine.size()));
    std::vector<int> displacements(counts.size(), 0);
    for (std::size_t r = 1; r < counts.size(); ++r)
        displacements[r] = displacements[r - 1] + counts[r - 1];
    std::vector<char> all(static_cast<std::size_t>(displacements.back() + counts.back()));
    MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_CHAR, all.data(), counts.data(),
                   displacements.data(), MPI_CHAR, MPI_COMM_WORLD);
    return all;
}

std::vector<std::vector<char>> Communicator::gather(const std::vector<char>& mine) const {
    if (size_ == 1) return {mine};
    const long n = static_cast<long>(mine.size());
    std::vector<long> sizes(static_cast<std::size_t>(size_));
    MPI_Gather(&n, 1, MPI_LONG, sizes.data(), 1, MPI_LONG, 0, MPI_COMM_WORLD);
    std::vector<std::vector<char>> out;
    if (rank_ != 0) {
        MPI_Send(mine.data(), static_cast<int>(n), MPI_CHAR, 0, 1, MPI_COMM_WORLD);
        return out;
    }
    out.push_back(mine);
    for (int r = 1; r < size_; ++r) {
        std::vector<char> bytes(static_cast<std::size_t>(sizes[static_cast<std::size_t>(r)]));
        MPI_Recv(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, r, 1, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        out.push_back(std::move(bytes));
    }
    return out;
}

void Communicator::abort(int exit_code) const {
    if (size_ > 1) MPI_Abort(MPI_COMM_WORLD, exit_code);
    std::exit(exit_code);
}

MpiSession::MpiSession(int& argc, char**& argv) {
    // Only under a launcher (mpirun, srun): a plain start stays one rank and pays nothing.
    if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE") &&
        !std::getenv("PMIX_RANK"))
        return;
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    MPI_Type_contiguous(sizeof(ValueIndex), MPI_BYTE, &g_value_index_type);
    MPI_Type_commit(&g_value_index_type);
    MPI_Op_create(min_loc_op, 1, &g_min_loc_op);
    g_world = new Communicator(rank, size);
}

MpiSession::~MpiSession() {
    if (!g_world) return;
    delete g_world;
    g_world = nullptr;
    MPI_Op_free(&g_min_loc_op);
    MPI_Type_free(&g_value_index_type);
    MPI_Finalize();
}

#else  // one rank

std::pair<Real, Index> Communicator::min_loc(Real value, Index index) const {
    return {value, index};
}
long Communicator::max(long value) const { return value; }
void Communicator::min(std::span<Real>) const {}
void Communicator::sum(std::span<ExactSum>) const {}
struct Communicator::Pending::Requests {};
Communicator::Pending Communicator::start_exchange(const std::vector<int>&,
                                                   const std::vector<std::vector<Real>>&,
                                                   std::vector<std::vector<Real>>&) const {
    return {};
}
void Communicator::wait(Pending&) const {}
std::vector<std::vector<char>> Communicator::gather(const std::vector<char>& mine) const {
    return {mine};
}
void Communicator::allgather(const std::vector<Real>& mine, const std::vector<int>&,
                             std::vector<Real>& all) const {
    all = mine;
}
std::vector<int> Communicator::allgather(int mine) const { return {mine}; }
std::vector<char> Communicator::allgather(const std::vector<char>& mine) const { return mine; }
void Communicator::abort(int exit_code) const { std::exit(exit_code); }
MpiSession::MpiSession(int&, char**&) {}
MpiSession::~MpiSession() = default;

#endif

Communicator::Pending::Pending() = default;
Communicator::Pending::~Pending() = default;
Communicator::Pending::Pending(Pending&&) noexcept = default;
Communicator::Pending& Communicator::Pending::operator=(Pending&&) noexcept = default;
bool Communicator::Pending::active() const { return requests_ != nullptr; }

}  // namespace fpmshell
