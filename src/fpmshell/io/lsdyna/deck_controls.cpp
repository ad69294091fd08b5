// The control cards (end time, time step, shell options, damping) and the output requests
// of a deck.
#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

void DeckTranslator::control(const DeckBlock& b) {
    const std::string& k = b.keyword;
    const Card f = card(b, 0);
    const Origin at{&b, f.line()};
    if (k == "CONTROL_TERMINATION") {
        end_time_ = Line{num(f.real(0, "ENDTIM")), at};
        const Real dtmin = f.real(2, "DTMIN");
        if (dtmin < 0 || dtmin >= 1)
            f.fail("DTMIN must be in [0, 1) (a fraction of the first step)");
        if (dtmin > 0) min_step_factor_ = Line{num(dtmin), at};
        if (f.id(1, "ENDCYC") != 0 || f.real(3, "ENDENG") != 0 || f.real(4, "ENDMAS") != 0)
            note(b, f.line(), "only ENDTIM and DTMIN are read (ENDCYC, ENDENG, ENDMAS ignored)");
    } else if (k == "CONTROL_TIMESTEP") {
        Real tssfac = f.real(1, "TSSFAC");
        if (tssfac == 0) tssfac = 0.9;
        control_.push_back({"  time_step_scale: " + num(tssfac), at});
        const Real dt2ms = f.real(4, "DT2MS");
        if (f.id(5, "LCTM") != 0) f.fail("LCTM (a curve of the largest step) is not supported");
        if (dt2ms > 0)
            f.fail(
                "DT2MS > 0 is not supported; DT2MS < 0 (mass added where the step is "
                "below TSSFAC x |DT2MS|) is");
        // MS1ST 1: mass added at the first step only, the step may fall below the target later
        const long long ms1st = f.id(7, "MS1ST");
        if (ms1st != 0 && ms1st != 1) f.fail("MS1ST must be 0 or 1");
        if (dt2ms < 0)
            control_.push_back({"  mass_scaling: {time_step: " + num(tssfac * -dt2ms) +
                                    (ms1st == 1 ? ", during_run: false}" : "}"),
                                at});
        if (f.id(2, "ISDO") != 0 || f.real(3, "TSLIMT") != 0)
            note(b, f.line(), "ISDO and TSLIMT ignored (fpmshell's own element step)");
        if (b.cards.size() > 1) {  // DT2MSF, DT2MSLC, IMSCL: mass scaling fpmshell has not
            const Card g = card(b, 1);
            if (g.real(0, "DT2MSF") != 0 && dt2ms == 0)
                g.fail(
                    "DT2MSF (mass scaling to a factor of the first step) is not supported; "
                    "DT2MS < 0 (mass scaling to a given step) is");
            if (g.id(1, "DT2MSLC") != 0)
                g.fail("DT2MSLC (a curve of the mass-scaling step) is not supported");
            if (g.id(2, "IMSCL") != 0) g.fail("IMSCL (selective mass scaling) is not supported");
        }
        if (f.real(0, "DTINIT") != 0)
            note(b, f.line(), "DTINIT ignored: the run starts with its own stable step");
        // ERODE: shells erode below TSMIN (DTMIN of *CONTROL_TERMINATION) with 10, 11, 110,
        // 111; with 0, 1, 100, 101 the run stops there (1 and 100 erode solids and beams,
        // which fpmshell's shells are not)
        const long long erode = f.id(6, "ERODE");
        if (erode != 0 && erode != 1 && erode != 10 && erode != 11 && erode != 100 &&
            erode != 101 && erode != 110 && erode != 111)
            f.fail("ERODE must be 0, 1, 10, 11, 100, 101, 110 or 111");
        erode_shells_ = erode % 100 >= 10;
    } else if (k == "CONTROL_SHELL") {
        const long long istupd = f.id(3, "ISTUPD");
        if (istupd == 1 || istupd == 4) control_.push_back({"  thickness_update: true", at});
        if (b.cards.size() > 1) {
            const Card g = card(b, 1);
            const long long intgrd = g.id(1, "INTGRD");
            if (intgrd != 0 && intgrd != 1) g.fail("INTGRD must be 0 (Gauss) or 1 (Lobatto)");
            if (intgrd == 1) lobatto_shells_ = Origin{&b, g.line()};
            // NFAIL1, NFAIL4 > 0: LS-DYNA deletes (1) or stops at (2) badly distorted shells
            if (g.id(5, "NFAIL1") > 0 || g.id(6, "NFAIL4") > 0)
                note(b, g.line(),
                     "NFAIL1, NFAIL4 not read: LS-DYNA's check of badly distorted quadrilaterals; "
                     "fpmshell's triangles have no such distortion, and a run stops (exit 1, "
                     "naming the element) at a degenerate one, or one turned over within a "
                     "step, instead of deleting it (theory.md §2.8)");
        }
        note(b, f.line(),
             "only ISTUPD and INTGRD are read (fpmshell's element has no other options here)");
    } else if (k == "DAMPING_GLOBAL") {
        if (f.id(0, "LCID") != 0) f.fail("LCID: damping that varies in time is not supported");
        bool scaled = false;
        for (std::size_t s = 2; s < 8; ++s) {
            const Real v = f.real(s, "STX..SRZ");
            scaled = scaled || (v != 0 && v != 1);
        }
        if (scaled) f.fail("STX..SRZ: damping scaled per direction is not supported");
        damping_ = Line{"damping: {mass: " + num(f.real(1, "VALDMP")) + "}", at};
    } else if (k == "CONTROL_UNITS") {
        note(b, b.line,
             "ignored: the deck's numbers are used as they are (fpmshell has no units of its own: "
             "they "
             "must be consistent, as LS-DYNA's must)");
    } else if (k == "CONTROL_SOLUTION") {
        if (const long long soln = f.id(0, "SOLN"); soln != 0)
            f.fail("SOLN " + std::to_string(soln) +
                   ": fpmshell solves the structural problem only (SOLN 0), not a thermal or "
                   "coupled one");
        note(b, b.line, "SOLN 0 (structural) is what fpmshell solves; the other fields ignored");
    } else if (k == "CONTROL_DAMPING" || k == "CONTROL_DYNAMIC_RELAXATION") {
        // NRCYCK, DRTOL, DRFCTR, DRTERM, TSSFDR, IRELAL, EDTTL, IDRFLG: dynamic relaxation
        if (const long long idrflg = f.id(7, "IDRFLG"); idrflg != 0)
            f.fail("IDRFLG " + std::to_string(idrflg) +
                   ": dynamic relaxation before the transient run is not supported (fpmshell's "
                   "quasi-static runs are control.mode: relaxation)");
        note(b, b.line, "IDRFLG 0: no dynamic relaxation, so its parameters are not used");
    } else if (k == "CONTROL_STRUCTURED" || k == "CONTROL_STRUCTURED_TERM") {
        note(b, b.line, "ignored: it asks for a structured copy of the input, not a model change");
    } else if (k == "CONTROL_ADAPTIVE" || k == "CONTROL_ADAPSTEP") {
        note(b, b.line,
             "ignored: fpmshell does not refine the mesh during a run (adaptive remeshing); the "
             "parts keep the deck's mesh, coarser than the one LS-DYNA would refine it to");
    } else if (k == "CONTROL_RIGID") {
        // LMF, JNTF, ORTHMD, PARTM, SPARSE, METALF, PLOTEL, RBSMS: joint formulations, a
        // faster update for forming tools, plotting, mass scaling of rigid bodies
        if (f.id(7, "RBSMS") != 0)
            f.fail("RBSMS: mass scaling that changes rigid bodies is not supported");
        note(b, b.line,
             "ignored: joint and update options of rigid bodies (fpmshell has no joints and "
             "moves its rigid bodies exactly)");
    } else if (k == "CONTROL_OUTPUT" || k == "CONTROL_ENERGY" || k == "CONTROL_HOURGLASS" ||
               k == "CONTROL_BULK_VISCOSITY" || k == "CONTROL_CONTACT" || k == "CONTROL_ACCURACY" ||
               k == "CONTROL_CPU" || k == "CONTROL_PARALLEL" || starts_with(k, "CONTROL_MPP")) {
        note(b, b.line,
             "ignored (output, hourglass, bulk viscosity or solver settings that "
             "fpmshell's shells do not use)");
    } else {
        refuse(b, unsupported_reason(k));
    }
}

void DeckTranslator::database(const DeckBlock& b) {
    const std::string& k = b.keyword;
    if (starts_with(k, "DATABASE_HISTORY_NODE")) {
        const bool with_id = k == "DATABASE_HISTORY_NODE_ID";
        if (!with_id && k != "DATABASE_HISTORY_NODE")
            refuse(b, "this history request is not supported");
        for (const DeckCard& dc : b.cards) {
            if (dc.blank()) continue;
            const Card f(deck_, b, dc, with_id ? std::vector<std::size_t>{10} : k_ten);
            for (std::size_t n = 0; n < f.size(); ++n) {
                const long long id = f.id(n, "NID");
                if (id > 0) history_nodes_.push_back({id, {&b, f.line()}});
            }
        }
        return;
    }
    const Card f = card(b, 0);
    const Real dt = f.real(0, "DT");
    if (k == "DATABASE_BINARY_D3PLOT") {
        const long long npltc = f.id(3, "NPLTC");
        if (npltc > 0)
            fields_every_npltc_ = npltc;
        else
            fields_every_ = Line{num(dt), {&b, f.line()}};
        return;
    }
    if (k == "DATABASE_GLSTAT" || k == "DATABASE_NODOUT" || k == "DATABASE_RWFORC" ||
        k == "DATABASE_RCFORC") {
        if (dt > 0 && (!every_ || dt < every_value_)) {
            every_value_ = dt;
            every_ = Line{num(dt), {&b, f.line()}};
        }
        if (k == "DATABASE_RWFORC") wall_forces_ = true;
        if (k == "DATABASE_RCFORC") contact_forces_ = true;
        return;
    }
    if (k == "DATABASE_MATSUM") {  // of its columns, each part's rigid-body velocity
        if (dt > 0 && (!every_ || dt < every_value_)) {
            every_value_ = dt;
            every_ = Line{num(dt), {&b, f.line()}};
        }
        part_velocities_ = Origin{&b, f.line()};
        note(b, b.line,
             "each part's velocity (its momentum over its mass, MATSUM's rigid-body "
             "velocity) as the histories part<PID>_vx, _vy, _vz; its energies are in "
             "energy.csv for the whole model only");
        return;
    }
    note(b, b.line,
         "ignored: an output fpmshell does not write (it writes history.csv, "
         "energy.csv and VTU frames)");
}

void DeckTranslator::write_control(std::vector<Line>& out) {
    if (!end_time_)
        throw InputError(input_error_text(path_, 0, "",
                                          "the deck has no *CONTROL_TERMINATION; its ENDTIM "
                                          "is the end time of the run"));
    add(out, "control:", end_time_->at);
    add(out, "  end_time: " + end_time_->text, end_time_->at);
    out.insert(out.end(), control_.begin(), control_.end());
    if (min_step_factor_)  // TSMIN = DTMIN x the first step; ERODE of *CONTROL_TIMESTEP
        add(out,
            "  minimum_time_step: {factor: " + min_step_factor_->text +
                (erode_shells_ ? ", erode: true}" : "}"),
            min_step_factor_->at);
}

void DeckTranslator::write_output(std::vector<Line>& out) {
    std::vector<Line> o;
    if (every_) o.push_back({"  every: " + every_->text, every_->at});
    if (fields_every_npltc_ > 0)
        o.push_back({"  fields_every: " +
                         num(std::stod(end_time_->text) / static_cast<Real>(fields_every_npltc_)),
                     end_time_->at});
    else if (fields_every_)
        o.push_back({"  fields_every: " + fields_every_->text, fields_every_->at});
    std::vector<Line> h;
    std::set<long long> seen;
    for (const auto& [id, at] : history_nodes_) {
        if (!seen.insert(id).second) continue;
        for (const char* q : {"ux", "uy", "uz", "vx", "vy", "vz", "ax", "ay", "az"})
            h.push_back({fmt::format("    - {{name: node{}_{}, nodes: node_{}, quantity: {}}}", id,
                                     q, id, q),
                         at});
    }
    if (wall_forces_)
        for (const WallDef& w : walls_)
            for (const char* c : {"x", "y", "z"})
                h.push_back({fmt::format("    - {{name: rigidwall{}_force_{}, quantity: "
                                         "rigid_rigidwall{}_force_{}}}",
                                         w.id, c, w.id, c),
                             w.at});
    std::set<long long> parts;  // of shells, and of rigid solids (their faces)
    for (const auto& [pid, part] : element_parts_) parts.insert(pid);
    for (const auto& [pid, part] : solid_parts_) parts.insert(pid);
    if (part_velocities_)
        for (const long long pid : parts)
            for (const char* c : {"x", "y", "z"})
                h.push_back({fmt::format("    - {{name: part{}_v{}, nodes: part_{}, quantity: v{}, "
                                         "reduce: mass_mean}}",
                                         pid, c, pid, c),
                             *part_velocities_});
    // the contact definitions come after the walls' in the model (write_walls)
    if (contact_forces_)
        for (std::size_t k = 0; k < contact_ids_.size(); ++k)
            for (const char* c : {"x", "y", "z"})
                h.push_back({fmt::format("    - {{name: contact{}_force_{}, quantity: "
                                         "contact_{}_force_{}}}",
                                         contact_ids_[k].first, c, walls_.size() + k + 1, c),
                             contact_ids_[k].second});
    if (!h.empty()) {
        o.push_back({"  histories:", h.front().at});
        o.insert(o.end(), h.begin(), h.end());
    }
    if (o.empty()) return;
    add(out, "output:", o.front().at);
    out.insert(out.end(), o.begin(), o.end());
}

}  // namespace fpmshell::deck
