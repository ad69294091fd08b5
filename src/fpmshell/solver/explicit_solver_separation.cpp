// Fracture by particle separation in the solver (theory.md §7.7): the failed elements open
// their sides (eq. 7.7-1), and once the open sides cut a particle's fan the run goes on with the
// solver of the separated mesh, built from the separated model and taking over this state.
#include <algorithm>
#include <functional>

#include "fpmshell/core/communicator.hpp"
#include "fpmshell/io/memory_archive.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

void ExplicitSolver::open_failed_sides() {
    // every rank's failed elements that wait for a side; each rank judges those it computes
    const std::vector<Index> waiting = ranks_.join_sorted(elements_.failed_unopened());
    if (waiting.empty()) return;
    const std::function<bool(Index)> failed = [&](Index e) {
        return elements_.cracked(e) || std::binary_search(waiting.begin(), waiting.end(), e);
    };
    const EdgeOpening::Mesh mesh{model_.triangles, topology_, s_.x, pinned_, failed};
    std::vector<Real> mine;  // records [element, the element across its side, the traction]
    for (const Index e : waiting) {
        if (!elements_.computes(e)) continue;
        const EdgeOpening::Choice c = opening_.side_to_open(mesh, e, elements_.membrane_force(e));
        if (c.across < 0) continue;
        mine.insert(mine.end(), {static_cast<Real>(e), static_cast<Real>(c.across), c.traction});
    }
    const std::vector<ElementPair> opened =
        opening_.open_chosen(mesh, ranks_.join_records(mine, 3));
    // a failed element has done its part once it has opened a side (the one it chose, or one
    // its neighbour chose: the crack has passed it)
    for (const Index e : waiting)
        if (opening_.open_sides_of(e) > 0) elements_.mark_opened(e);
    if (opened.empty()) return;
    // the separation the open sides call for (the same on every rank: it depends on the mesh
    // and the set of open sides alone)
    history_.opened.insert(history_.opened.end(), opened.begin(), opened.end());
    Separation separation = separate_along_edges(model_.triangles, model_.nodes.size(),
                                                 unsplit_edges(model_.triangles, opening_.open()));
    if (!separation.splits.empty()) separation_due_ = std::move(separation);
}

ExplicitSolver::ExplicitSolver(const Model& separated, ExplicitSolver& before,
                               const Separation& separation)
    : ExplicitSolver(separated) {
    take_state(before, separation);
}

void ExplicitSolver::take_state(ExplicitSolver& before, const Separation& separation) {
    const Communicator& comm = Communicator::world();
    // the particles' state before, whole (a distributed run's: every rank's owned particles)
    before.ranks_.finish_positions(before.s_.x);  // the step's last messages
    ParticleState old;
    if (before.ranks_.distributed()) {
        old.resize(before.s_.size());
        std::vector<std::uint8_t> seen(before.s_.size(), 0);
        RankExchange::read_particle_records(
            comm.allgather(before.ranks_.owned_particle_records(before.s_)), old, seen);
    } else {
        old = std::move(before.s_);
    }
    const std::size_t n_old = old.size(), n = s_.size();
    std::vector<std::size_t> source(n);  // the particle before that each one continues
    for (std::size_t p = 0; p < n; ++p)
        source[p] = p < n_old ? p : static_cast<std::size_t>(separation.parent_of_new[p - n_old]);
    for (std::vector<Vec3> ParticleState::*field :
         {&ParticleState::x, &ParticleState::x_prev, &ParticleState::v, &ParticleState::v_prev,
          &ParticleState::omega, &ParticleState::omega_prev, &ParticleState::dtheta,
          &ParticleState::normal})
        for (std::size_t p = 0; p < n; ++p) (s_.*field)[p] = (old.*field)[source[p]];
    for (std::size_t p = 0; p < n; ++p) s_.rotation[p] = old.rotation[source[p]];
    for (std::size_t p = 0; p < n_old; ++p) {
        s_.mass[p] = old.mass[p];
        s_.inertia[p] = old.inertia[p];
    }
    // eq. 7.7-2: the parts of a split particle take its mass and rotary inertia (with what mass
    // scaling and point masses gave it) in the proportion of their groups' lumped shares, cut
    // exactly; its loads of the step (their works' trapezoid reads them) in the same proportion
    using Loads = std::vector<Vec3> ParticleState::*;
    const Loads loads[] = {&ParticleState::f_int,         &ParticleState::m_int,
                           &ParticleState::f_ext,         &ParticleState::m_ext,
                           &ParticleState::f_ext_prev,    &ParticleState::m_ext_prev,
                           &ParticleState::reaction,      &ParticleState::reaction_moment,
                           &ParticleState::reaction_prev, &ParticleState::reaction_moment_prev,
                           &ParticleState::f_contact,     &ParticleState::f_contact_prev};
    for (const Loads field : loads)
        for (std::size_t p = 0; p < n_old; ++p) (s_.*field)[p] = (old.*field)[p];
    for (const ParticleSplit& split : separation.splits) {
        const auto parent = static_cast<std::size_t>(split.parent);
        for (const bool inertia : {false, true}) {
            const std::vector<Real>& lumped =
                inertia ? topology_.particle_inertia : topology_.particle_mass;
            Real total = lumped[parent];
            for (const Index c : split.children) total += lumped[static_cast<std::size_t>(c)];
            const Real whole = inertia ? old.inertia[parent] : old.mass[parent];
            std::vector<Real> shares;
            for (const Index c : split.children)
                shares.push_back(total > 0 ? whole * (lumped[static_cast<std::size_t>(c)] / total)
                                           : 0.0);
            const std::vector<Real> parts = split_exactly(whole, shares);
            std::vector<Real>& out = inertia ? s_.inertia : s_.mass;
            out[parent] = parts[0];
            for (std::size_t k = 0; k < split.children.size(); ++k)
                out[static_cast<std::size_t>(split.children[k])] = parts[k + 1];
        }
        for (const Loads field : loads) {
            Vec3& at_parent = (s_.*field)[parent];
            const Vec3 whole = at_parent;
            for (const Index c : split.children) {
                const auto uc = static_cast<std::size_t>(c);
                const Real share = old.mass[parent] > 0 ? s_.mass[uc] / old.mass[parent] : 0.0;
                (s_.*field)[uc] = share * whole;
                at_parent -= (s_.*field)[uc];
            }
        }
    }
    for (std::size_t p = 0; p < n; ++p) {
        bc_->prescribed_rotation_applied()[p] =
            before.bc_->prescribed_rotation_applied()[source[p]];
        s_.drill_axis[p] = bc_->drill_axis(p, s_.normal[p]);
    }
    // every element's state (the elements keep their numbers)
    std::vector<std::uint8_t> seen(elements_.size(), 0);
    elements_.unpack_state(comm.allgather(before.elements_.pack_state()), seen);
    // the cycle's own state
    time_ = before.time_;
    dt_half_ = before.dt_half_;
    dt_half_prev_ = before.dt_half_prev_;
    dt_center_ = before.dt_center_;
    steps_ = before.steps_;
    restart_ = before.restart_;
    element_steps_ = before.element_steps_;
    eroded_elements_ = before.eroded_elements_;
    first_erosion_time_ = before.first_erosion_time_;
    residual2_ = before.residual2_;
    reference2_ = before.reference2_;
    min_dt_element_ = before.min_dt_element_;
    min_step_ = before.min_step_;  // of the run's first step, not the separated mesh's
    if (model_.control.minimum_time_step.erode)
        elements_.set_erosion_step(min_step_ / model_.control.time_step_scale);
    energy_ = before.energy_;
    bodies_ = before.bodies_;
    added_mass_ = before.added_mass_;
    opening_ = before.opening_;
    history_ = before.history_;
    history_.splits.push_back(history_.opened.size());
    split_particles_ =
        before.split_particles_ + static_cast<Index>(separation.parent_of_new.size());
    // the welds and ties as they were (their particles never split)
    MemoryArchive welds;
    before.nodal_rigid_bodies_.transfer(welds);
    welds.rewind();
    nodal_rigid_bodies_.transfer(welds);
    if (nodal_rigid_bodies_.failed_welds() > 0) {
        nodal_rigid_bodies_.rebuild();
        release_failed_welds();
    }
    if (tied_) {
        MemoryArchive ties;
        before.tied_->transfer(ties);
        ties.rewind();
        tied_->transfer(ties);
    }
    // the contact searches the new mesh afresh, with the masses reached
    if (contact_) {
        contact_->continue_from(*before.contact_);
        for (std::size_t p = 0; p < s_.size(); ++p)
            contact_->set_inverse_mass(static_cast<Index>(p),
                                       bc_->free_inverse_mass(p, s_.mass[p]));
        contact_->drop_faces(elements_.eroded_so_far(), true);
    }
    refresh_contact_masses();
    loads_->unload(elements_.eroded_so_far());
    elements_.mark_small_pieces(elements_.eroded_so_far());  // eq. 6.4-3
    ranks_.start_positions(s_.x);                            // as the step before ended
}

}  // namespace fpmshell
