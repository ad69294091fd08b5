// The traffic between the ranks of a distributed run; described in rank_exchange.hpp.
#include "fpmshell/solver/rank_exchange.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "fpmshell/core/byte_buffer.hpp"
#include "fpmshell/solver/unit_partition.hpp"

namespace fpmshell {

RankExchange::RankExchange(const Model& model, const MeshTopology& topology,
                           const ShellElements& elements) {
    const Communicator& comm = Communicator::world();
    d_ = decompose(model, topology, elements.assembly(),
                   element_costs(model, elements.assembly().blocks()), comm.rank(), comm.size());
}

RankExchange::~RankExchange() {
    if (positions_in_flight_.active()) Communicator::world().wait(positions_in_flight_);
}

void RankExchange::set_whole_particles(Whole part, const std::vector<Index>& particles) {
    WholeParticles& w = whole_[static_cast<std::size_t>(part)];
    w.owned.assign(d_.distributed() ? static_cast<std::size_t>(d_.ranks) : 0, {});
    if (!d_.distributed()) return;
    for (const Index p : particles)
        w.owned[static_cast<std::size_t>(d_.particle_owner[static_cast<std::size_t>(p)])].push_back(
            p);
}

void RankExchange::share(Whole part, std::initializer_list<std::vector<Vec3>*> arrays) {
    if (!d_.distributed()) return;
    WholeParticles& w = whole_[static_cast<std::size_t>(part)];
    const int per_particle = 3 * static_cast<int>(arrays.size());
    w.send.clear();
    for (const Index p : w.owned[static_cast<std::size_t>(d_.rank)])
        for (const std::vector<Vec3>* a : arrays) {
            const Vec3& v = (*a)[static_cast<std::size_t>(p)];
            w.send.insert(w.send.end(), v.data(), v.data() + 3);
        }
    std::vector<int> counts;
    for (const auto& owned : w.owned)
        counts.push_back(per_particle * static_cast<int>(owned.size()));
    Communicator::world().allgather(w.send, counts, w.all);
    std::size_t at = 0;
    for (const auto& owned : w.owned)
        for (const Index p : owned)
            for (std::vector<Vec3>* a : arrays) {
                (*a)[static_cast<std::size_t>(p)] = Vec3(w.all[at], w.all[at + 1], w.all[at + 2]);
                at += 3;
            }
}

void RankExchange::start_positions(const std::vector<Vec3>& x) {
    if (!d_.distributed()) return;
    const DomainDecomposition& d = d_;
    const std::size_t n_peers = d.position_peers.size();
    position_send_.resize(n_peers);
    position_recv_.resize(n_peers);
    for (std::size_t k = 0; k < n_peers; ++k) {
        std::vector<Real>& out = position_send_[k];
        out.resize(3 * d.position_send[k].size());
        for (std::size_t i = 0; i < d.position_send[k].size(); ++i) {
            const Vec3& xp = x[static_cast<std::size_t>(d.position_send[k][i])];
            for (int c = 0; c < 3; ++c) out[3 * i + static_cast<std::size_t>(c)] = xp[c];
        }
        position_recv_[k].resize(3 * d.position_recv[k].size());
    }
    positions_in_flight_ =
        Communicator::world().start_exchange(d.position_peers, position_send_, position_recv_);
}

void RankExchange::finish_positions(std::vector<Vec3>& x) {
    if (!positions_in_flight_.active()) return;
    const DomainDecomposition& d = d_;
    Communicator::world().wait(positions_in_flight_);
    for (std::size_t k = 0; k < d.position_peers.size(); ++k)
        for (std::size_t i = 0; i < d.position_recv[k].size(); ++i) {
            Vec3& xp = x[static_cast<std::size_t>(d.position_recv[k][i])];
            for (int c = 0; c < 3; ++c)
                xp[c] = position_recv_[k][3 * i + static_cast<std::size_t>(c)];
        }
}

namespace {
/// Every array of a particle's state, in one order for writing and reading.
template <class F>
void for_each_particle_field(ParticleState& s, std::size_t p, F&& f) {
    for (std::vector<Vec3>* a : {&s.x0,
                                 &s.x,
                                 &s.x_prev,
                                 &s.v,
                                 &s.v_prev,
                                 &s.omega,
                                 &s.omega_prev,
                                 &s.dtheta,
                                 &s.normal,
                                 &s.drill_axis,
                                 &s.f_int,
                                 &s.m_int,
                                 &s.f_ext,
                                 &s.m_ext,
                                 &s.f_ext_prev,
                                 &s.m_ext_prev,
                                 &s.reaction,
                                 &s.reaction_moment,
                                 &s.reaction_prev,
                                 &s.reaction_moment_prev,
                                 &s.f_contact,
                                 &s.f_contact_prev})
        f((*a)[p]);
    f(s.rotation[p]);
    f(s.mass[p]);
    f(s.inertia[p]);
    f(s.full_rotation[p]);
}
}  // namespace

std::vector<char> RankExchange::owned_particle_records(ParticleState& s) const {
    const DomainDecomposition& d = d_;
    std::vector<char> bytes;
    const auto put = [&](std::size_t p) {
        append_bytes(bytes, static_cast<Index>(p));
        for_each_particle_field(s, p, [&](auto& v) { append_bytes(bytes, v); });
    };
    if (!d.distributed()) {
        for (std::size_t p = 0; p < s.size(); ++p) put(p);
        return bytes;
    }
    for (const Index a : d.own_atoms)
        for (Index k = d.atom_particle_begin[static_cast<std::size_t>(a)];
             k < d.atom_particle_begin[static_cast<std::size_t>(a) + 1]; ++k)
            put(static_cast<std::size_t>(d.atom_particles[static_cast<std::size_t>(k)]));
    return bytes;
}

void RankExchange::read_particle_records(const std::vector<char>& bytes, ParticleState& s,
                                         std::vector<std::uint8_t>& seen) {
    std::size_t record = sizeof(Index);
    {
        ParticleState one;
        one.resize(1);
        for_each_particle_field(one, 0, [&](auto& v) { record += sizeof(v); });
    }
    if (bytes.size() % record != 0)
        throw std::invalid_argument("the particle records are cut short");
    std::size_t at = 0;
    while (at < bytes.size()) {
        Index p = 0;
        read_bytes(bytes, at, p);
        if (p < 0 || static_cast<std::size_t>(p) >= s.size())
            throw std::invalid_argument(fmt::format("a record of particle {} of {}", p, s.size()));
        const auto up = static_cast<std::size_t>(p);
        for_each_particle_field(s, up, [&](auto& v) { read_bytes(bytes, at, v); });
        ++seen[up];
    }
}

std::vector<Index> RankExchange::join_sorted(std::vector<Index> mine) const {
    if (d_.distributed()) {
        const Communicator& comm = Communicator::world();
        const std::vector<Real> sent(mine.begin(), mine.end());
        const std::vector<int> counts = comm.allgather(static_cast<int>(sent.size()));
        std::vector<Real> all;
        comm.allgather(sent, counts, all);
        mine.assign(all.begin(), all.end());
    }
    std::sort(mine.begin(), mine.end());
    return mine;
}

std::vector<Real> RankExchange::join_records(const std::vector<Real>& mine,
                                             std::size_t width) const {
    if (!d_.distributed()) return mine;
    const Communicator& comm = Communicator::world();
    const std::vector<int> counts = comm.allgather(static_cast<int>(mine.size()));
    std::vector<Real> all;
    comm.allgather(mine, counts, all);
    // each rank's records are in order: sort the records of all by their first number
    std::vector<std::size_t> order(all.size() / width);
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return all[width * a] < all[width * b]; });
    std::vector<Real> joined;
    joined.reserve(all.size());
    for (const std::size_t i : order)
        joined.insert(joined.end(), all.begin() + static_cast<std::ptrdiff_t>(width * i),
                      all.begin() + static_cast<std::ptrdiff_t>(width * (i + 1)));
    return joined;
}

Real RankExchange::max(Real value) const {
    if (!d_.distributed()) return value;
    return -Communicator::world().min_loc(-value, 0).first;  // the smallest of its negative
}

}  // namespace fpmshell
