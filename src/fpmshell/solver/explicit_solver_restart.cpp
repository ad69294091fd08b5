// The solver's state in a restart file (io/restart_archive.hpp): whole in restart.bin, or on
// several ranks cut into the pieces every rank writes of its own particles and elements
// (model-format.md "Restart files").
#include <fmt/format.h>

#include <exception>
#include <string>

#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

template <class Archive>
void ExplicitSolver::transfer_state(Archive& ar, bool particles) {
    ar(time_, dt_half_, dt_half_prev_, dt_center_, steps_, restart_, element_steps_);
    ar(eroded_elements_, first_erosion_time_);
    if (particles) ar(s_);
    ar(energy_, bodies_, bc_->prescribed_rotation_applied());
}

void ExplicitSolver::save(RestartWriter& out, bool in_pieces) const {
    auto& self = const_cast<ExplicitSolver&>(*this);  // the archive's interface is shared with load
    out.section("separation");  // first: the run's model is made from it before the load (§7.7)
    out(self.history_.opened, self.history_.splits, self.split_particles_);
    out.section("solver");
    self.transfer_state(out, !in_pieces);
    out.section("elements");
    if (!in_pieces) elements_.save(out);
    out.section("mass_scaling");
    if (!in_pieces) self.elements_.time_steps().transfer_masses(out);
    out(self.added_mass_);
    out.section("contact");
    out(static_cast<bool>(contact_));
    if (contact_) contact_->save(out);
    out.section("ties");
    if (tied_) self.tied_->transfer(out);
    out.section("welds");
    self.nodal_rigid_bodies_.transfer(out);
}

void ExplicitSolver::save_piece(RestartWriter& out) const {
    auto& self = const_cast<ExplicitSolver&>(*this);  // the records are read, not changed
    const DomainDecomposition& d = ranks_.decomposition();
    out.section("piece");
    out(d.rank, d.ranks, steps_, time_);
    out.section("particles");
    out.put_block(ranks_.owned_particle_records(self.s_));
    out.section("elements");
    out.put_block(elements_.pack_state());
}

void ExplicitSolver::load_pieces(const RestartReader& in, int ranks, const RestartPieces& pieces) {
    std::vector<std::uint8_t> particle_seen(s_.size(), 0), element_seen(elements_.size(), 0);
    for (int r = 0; r < ranks; ++r) {
        RestartReader piece = pieces(r);
        piece.section("piece");
        int rank = -1, of = 0;
        long steps = -1;
        Real time = -1;
        piece(rank, of, steps, time);
        if (rank != r || of != ranks || steps != steps_ || time != time_)
            piece.fail(
                fmt::format("restart piece of rank {} of {} after step {}, where {} "
                            "expects rank {} of {} after step {}",
                            rank, of, steps, in.path().filename().string(), r, ranks, steps_));
        std::vector<char> particles, elements;
        piece.section("particles");
        piece(particles);
        piece.section("elements");
        piece(elements);
        piece.finish();
        try {
            RankExchange::read_particle_records(particles, s_, particle_seen);
            elements_.unpack_state(elements, element_seen);
        } catch (const std::exception& e) {
            piece.fail(fmt::format("restart piece is damaged: {}", e.what()));
        }
    }
    for (const std::vector<std::uint8_t>* seen : {&particle_seen, &element_seen})
        for (const std::uint8_t n : *seen)
            if (n != 1)
                in.fail(
                    fmt::format("restart file of another model: {} not hold every "
                                "particle and element of this mesh once",
                                ranks == 1 ? std::string("its piece does")
                                           : fmt::format("its {} pieces do", ranks)));
}

void ExplicitSolver::load(RestartReader& in, int pieces, const RestartPieces& open_piece) {
    // Every list of the state has one entry per particle, rigid body, element or section of the
    // model: a file whose lists have other lengths is of another model (or damaged), and is
    // refused before any of them is used as the model's.
    const bool whole = pieces == 0;
    // §7.7 the separations of the run, which the model this solver was built from must have
    // made already (replay_separations)
    in.section("separation");
    SeparationHistory history;
    Index split_particles = 0;
    in(history.opened, history.splits, split_particles);
    if (!history.splits.empty() && model_.separated_from.empty())
        in.fail(
            fmt::format("restart file of a run whose particles separated {} times "
                        "(theory.md §7.7), loaded into the mesh as read",
                        history.splits.size()));
    history_ = std::move(history);
    split_particles_ = split_particles;
    if (elements_.separates()) {
        opening_ = EdgeOpening(model_.n_elements());
        opening_.add(history_.opened);
    }
    LengthRecorder model_lengths;
    transfer_state(model_lengths, whole);
    in.section("solver");
    const std::size_t n_bodies = bodies_.size();
    transfer_state(in, whole);
    if (bodies_.size() != n_bodies) in.fail("restart file of a model with other rigid bodies");
    LengthRecorder loaded_lengths;
    transfer_state(loaded_lengths, whole);
    if (loaded_lengths.lengths != model_lengths.lengths)
        in.fail("restart file of another model: its particle fields do not fit this mesh");
    if (!whole) load_pieces(in, pieces, open_piece);
    // The model's initial positions must be those the run started from, bit for bit.
    if (s_.x0 != model_.nodes)
        in.fail("restart file of another model: its particles are not those of this mesh");
    for (std::size_t p = 0; p < s_.size(); ++p) s_.drill_axis[p] = bc_->drill_axis(p, s_.normal[p]);
    in.section("elements");
    if (whole) elements_.load(in);
    in.section("mass_scaling");
    const std::vector<std::size_t> mass_lengths = stored_lengths(added_mass_);
    if (whole) {
        LengthRecorder masses;
        elements_.time_steps().transfer_masses(masses);
        elements_.time_steps().transfer_masses(in);
        LengthRecorder loaded_masses;
        elements_.time_steps().transfer_masses(loaded_masses);
        if (loaded_masses.lengths != masses.lengths)
            in.fail("restart file of another model: its element masses do not fit this mesh");
    }
    in(added_mass_);
    if (stored_lengths(added_mass_) != mass_lengths)
        in.fail("restart file of another model: its element masses do not fit this mesh");
    // the contact's inverse masses follow the masses the run had reached (§6.10)
    if (contact_)
        for (std::size_t p = 0; p < s_.size(); ++p)
            contact_->set_inverse_mass(static_cast<Index>(p),
                                       bc_->free_inverse_mass(p, s_.mass[p]));
    refresh_contact_masses();
    in.section("contact");
    bool has_contact = false;
    in(has_contact);
    if (has_contact != static_cast<bool>(contact_))
        in.fail("restart file of a model with other contact definitions");
    if (contact_) {
        contact_->load(in);
        // §7.6: the faces eroded before the stop; the loaded candidates are already without
        contact_->drop_faces(elements_.eroded_so_far(), false);
    }
    loads_->unload(elements_.eroded_so_far());  // §7.6: their pressures and blasts stopped
    elements_.mark_small_pieces(elements_.eroded_so_far());  // eq. 6.4-3
    in.section("ties");
    if (tied_) {
        tied_->transfer(in);
        if (!tied_->restored()) in.fail("restart file of a model with other ties");
    }
    in.section("welds");
    nodal_rigid_bodies_.transfer(in);
    if (!nodal_rigid_bodies_.restored()) in.fail("restart file of a model with other spot welds");
    if (nodal_rigid_bodies_.failed_welds() > 0) {
        nodal_rigid_bodies_.rebuild();
        release_failed_welds();
    }
}

}  // namespace fpmshell
