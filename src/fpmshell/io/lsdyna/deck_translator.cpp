// The deck translator's passes, its table from keyword to reader, its notes and the model's
// layout (see deck_translator.hpp).
#include "fpmshell/io/lsdyna/deck_translator.hpp"

#include <algorithm>
#include <filesystem>
#include <numeric>

#include "fpmshell/failure/failure_criterion.hpp"
#include "fpmshell/materials/material_law.hpp"

namespace fpmshell::deck {
namespace {

struct CardReader {
    const char* keyword;  ///< the keyword, or its beginning when `prefix`
    bool prefix;
    DeckTranslator::Pass pass;
    DeckTranslator::Reader read;
};

using P = DeckTranslator::Pass;
using T = DeckTranslator;

/// Every keyword the translator knows, the first match read; any other is refused.
const std::vector<CardReader>& card_readers() {
    static const std::vector<CardReader> readers = {
        {"TITLE", false, P::Definitions, &T::title},
        {"NODE", false, P::Definitions, &T::mesh_only},
        {"ELEMENT_SHELL", true, P::Definitions, &T::element_shell},
        {"ELEMENT_SOLID", false, P::Definitions, &T::element_solid},
        {"ELEMENT_MASS", true, P::References, &T::element_mass},
        {"SET_NODE", true, P::Definitions, &T::set_header},
        {"SET_SHELL", true, P::Definitions, &T::set_header},
        {"SET_PART", true, P::Definitions, &T::set_header},
        {"SET_SEGMENT", true, P::Definitions, &T::segment_set},
        {"PART", false, P::Definitions, &T::part},
        {"PART_INERTIA", false, P::Definitions, &T::part_inertia},
        {"PART_MOVE", false, P::References, &T::part_move},
        {"SECTION_SHELL", true, P::Definitions, &T::section_shell},
        {"SECTION_SOLID", false, P::Definitions, &T::section_solid},
        {"SECTION_SOLID_TITLE", false, P::Definitions, &T::section_solid},
        {"INTEGRATION_SHELL", false, P::Definitions, &T::integration_shell},
        {"MAT_ADD_", true, P::References, &T::add_failure_card},
        {"MAT_", true, P::Definitions, &T::material},
        {"DEFINE_CURVE", true, P::Definitions, &T::define_curve},
        {"DEFINE_TABLE", true, P::Definitions, &T::define_table},
        {"BOUNDARY_SPC_", true, P::References, &T::spc},
        {"BOUNDARY_PRESCRIBED_MOTION_", true, P::References, &T::prescribed_motion},
        {"INITIAL_VELOCITY", true, P::References, &T::initial_velocity},
        {"LOAD_SEGMENT", true, P::References, &T::segment_load},
        {"LOAD_BLAST_ENHANCED", false, P::Definitions, &T::blast_source},
        {"LOAD_BLAST_SEGMENT", true, P::References, &T::blast_segment_load},
        {"LOAD_NODE_", true, P::References, &T::load},
        {"LOAD_BODY_", true, P::References, &T::body_load},
        {"LOAD_SHELL_SET", true, P::References, &T::load},
        {"RIGIDWALL_PLANAR", true, P::References, &T::rigid_wall},
        {"RIGIDWALL_GEOMETRIC", true, P::References, &T::geometric_wall},
        {"CONTACT_AUTOMATIC_SINGLE_SURFACE", true, P::References, &T::contact},
        {"CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", true, P::References, &T::contact},
        {"CONTACT_AUTOMATIC_NODES_TO_SURFACE", true, P::References, &T::contact},
        {"CONTACT_AUTOMATIC_GENERAL", true, P::References, &T::contact},
        {"CONTACT_SINGLE_SURFACE", true, P::References, &T::contact},
        {"CONTACT_SURFACE_TO_SURFACE", true, P::References, &T::contact},
        {"CONTACT_NODES_TO_SURFACE", true, P::References, &T::contact},
        {"CONTACT_TIED_NODES_TO_SURFACE", true, P::References, &T::tied_contact},
        {"CONTACT_TIED_SHELL_EDGE_TO_SURFACE", true, P::References, &T::tied_contact},
        {"CONTACT_TIED_SURFACE_TO_SURFACE", true, P::References, &T::tied_contact},
        {"CONTACT_TIEBREAK_NODES_TO_SURFACE", true, P::References, &T::tied_contact},
        {"CONTACT_TIEBREAK_SURFACE_TO_SURFACE", true, P::References, &T::tied_contact},
        {"CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE", true, P::References, &T::contact},
        {"CONTACT_FORMING_SURFACE_TO_SURFACE", true, P::References, &T::contact},
        {"CONTACT_FORMING_NODES_TO_SURFACE", true, P::References, &T::contact},
        {"CONTACT_ERODING_", true, P::References, &T::contact},
        {"CONSTRAINED_NODAL_RIGID_BODY", true, P::References, &T::nodal_rigid_body},
        {"CONSTRAINED_RIGID_BODIES", true, P::References, &T::rigid_bodies_joined},
        {"CONSTRAINED_EXTRA_NODES", true, P::References, &T::extra_nodes},
        {"CONSTRAINED_SPOTWELD", true, P::References, &T::spot_weld},
        {"CONSTRAINED_GENERALIZED_WELD", true, P::References, &T::generalized_spot_weld},
        {"CONTROL_", true, P::References, &T::control},
        {"DAMPING_GLOBAL", false, P::References, &T::control},
        {"DATABASE_", true, P::References, &T::database},
        {"EOS_", true, P::References, &T::ignored},
        {"HOURGLASS", false, P::References, &T::ignored},
        {"SENSOR_", true, P::References, &T::ignored},
        {"PART_CONTACT", false, P::References, &T::ignored},
        {"COMMENT", false, P::References, &T::ignored},
        {"KEYWORD_ID", false, P::References, &T::ignored},
        {"DEFINE_BOX", true, P::References, &T::ignored},
        {"INTERFACE_SPRINGBACK", true, P::References, &T::ignored},
        {"DEFINE_COORDINATE", true, P::Definitions, &T::define_coordinate},
    };
    return readers;
}

const CardReader* reader_of(const std::string& keyword) {
    for (const CardReader& r : card_readers())
        if (r.prefix ? starts_with(keyword, r.keyword) : keyword == r.keyword) return &r;
    return nullptr;
}

/// A block's text without its place: its keyword and its cards, trailing blanks dropped.
std::string block_text(const DeckBlock& b) {
    std::string s = b.keyword;
    for (const DeckCard& c : b.cards) {
        std::size_t end = c.text.find_last_not_of(" \t\r");
        s += '\n';
        s += c.text.substr(0, end == std::string::npos ? 0 : end + 1);
    }
    return s;
}

/// The family a block is numbered in when it carries no id: RIGIDWALL or CONTACT ("" else).
std::string numbered_family(const std::string& keyword) {
    for (const char* f : {"RIGIDWALL", "CONTACT"})
        if (starts_with(keyword, f)) return f;
    return "";
}

}  // namespace

DeckTranslator::DeckTranslator(const std::string& path, std::string mesh_file)
    : path_(path), mesh_file_(std::move(mesh_file)), deck_(read_keyword_deck(path)) {
    notes_ = deck_.notes;  // what the keyword reader noted (duplicate parameters, empty includes)
    std::map<std::string, long long> count;
    for (const DeckBlock& b : deck_.blocks)
        if (const std::string f = numbered_family(b.keyword); !f.empty())
            reading_numbers_[&b] = ++count[f];
}

DeckTranslation DeckTranslator::translate() {
    // Pass 1, in reading order: a *DEFINE_TABLE's curves are the *DEFINE_CURVE cards that
    // follow it.
    std::vector<const DeckBlock*> references;
    for (const DeckBlock& b : deck_.blocks) {
        const CardReader* r = reader_of(b.keyword);
        if (r == nullptr)
            unsupported(b);
        else if (r->pass == Pass::Definitions)
            (this->*(r->read))(b);
        else
            references.push_back(&b);
    }
    // Pass 2, in the order of the cards' text (ties: reading order): the model's lists (loads
    // that add up on a particle, contacts, constraints) do not follow the cards' places.
    std::vector<std::string> texts;
    texts.reserve(references.size());
    for (const DeckBlock* b : references) texts.push_back(block_text(*b));
    std::vector<std::size_t> order(references.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return texts[a] < texts[b]; });
    for (const std::size_t k : order)
        (this->*(reader_of(references[k]->keyword)->read))(*references[k]);
    return write();
}

void DeckTranslator::title(const DeckBlock& b) {
    if (!b.cards.empty()) title_ = trim(b.cards[0].text);
}

/// *NODE: read by the mesh reader (mesh/lsdyna_reader.hpp) alone.
void DeckTranslator::mesh_only(const DeckBlock&) {}

void DeckTranslator::ignored(const DeckBlock& b) { note(b, b.line, ignored_reason(b.keyword)); }

void DeckTranslator::unsupported(const DeckBlock& b) { refuse(b, unsupported_reason(b.keyword)); }

std::string DeckTranslator::place(const Origin& at) {
    return at.block == nullptr ? std::string("?") : at.block->file + ":" + std::to_string(at.line);
}

long long DeckTranslator::reading_number(const DeckBlock& b) const {
    const auto it = reading_numbers_.find(&b);
    return it == reading_numbers_.end() ? 0 : it->second;
}

void DeckTranslator::note(const DeckBlock& b, int line, const std::string& what) {
    notes_.push_back(input_error_text(b.file, line, "", "*" + b.keyword + ": " + what));
}

void DeckTranslator::refuse(const DeckBlock& b, const std::string& why) {
    deck_fail(b, b.line, why);
}

/// Card k of the block; an optional card left out reads as blank fields.
Card DeckTranslator::card(const DeckBlock& b, std::size_t k,
                          const std::vector<std::size_t>& widths) {
    if (k >= b.cards.size())
        return Card(deck_, b, DeckCard{b.cards.empty() ? b.line : b.cards.back().line, ""}, widths);
    return Card(deck_, b, b.cards[k], widths);
}

Card DeckTranslator::required_card(const DeckBlock& b, std::size_t k, const char* what,
                                   const std::vector<std::size_t>& widths) {
    if (k >= b.cards.size()) deck_fail(b, b.line, std::string("needs its card of ") + what);
    return Card(deck_, b, b.cards[k], widths);
}

std::string DeckTranslator::ignored_reason(const std::string& k) {
    if (starts_with(k, "EOS_"))
        return "ignored: an equation of state has no part in a shell's plane stress";
    if (k == "HOURGLASS") return "ignored: fpmshell's triangles have no hourglass modes";
    if (starts_with(k, "SENSOR_"))
        return "ignored: no control of this deck uses a sensor that fpmshell reads";
    if (k == "PART_CONTACT")
        return "ignored: contact parameters per part (fpmshell's contact takes each shell's "
               "thickness)";
    if (k == "KEYWORD_ID") return "ignored: the deck's identification, not a model card";
    if (starts_with(k, "INTERFACE_SPRINGBACK"))
        return "ignored: it asks for the formed state as the input of a springback run "
               "(a dynain file), an output fpmshell does not write";
    return "ignored: only the cards that use it would need it, and fpmshell refuses those";
}

std::string DeckTranslator::unsupported_reason(const std::string& k) {
    if (starts_with(k, "MAT_ADD_")) {  // the cards of failure/failure_criteria.cpp
        std::string list;
        for (const FailureCriterion& c : failure_criteria())
            for (const DeckFailureCard& d : c.deck_cards)
                list += (list.empty() ? "*" : ", *") + d.keywords.front();
        return "this card is not supported; of the cards that add failure to a material, "
               "fpmshell reads " +
               list;
    }
    if (starts_with(k, "MAT_")) {  // the cards of the laws of materials/material_laws.cpp
        std::vector<std::pair<std::string, std::string>> cards;  // (number, name)
        for (const MaterialLaw& law : material_laws())
            for (const DeckMaterialCard& c : law.deck_cards)
                cards.emplace_back(c.keywords.back().substr(4), c.keywords.front());
        std::sort(cards.begin(), cards.end());
        std::string list;
        for (std::size_t i = 0; i < cards.size(); ++i)
            list += (i == 0                  ? ""
                     : i + 1 == cards.size() ? " and "
                                             : ", ") +
                    ("*" + cards[i].second) + " (" + cards[i].first + ")";
        return "this material is not supported; fpmshell reads " + list;
    }
    if (starts_with(k, "SECTION_") && !starts_with(k, "SECTION_SHELL"))
        return "fpmshell models shells only (*SECTION_SHELL, and *SECTION_SOLID for parts of "
               "*MAT_RIGID); beam, discrete and thick-shell sections are not supported";
    if (starts_with(k, "ELEMENT_SOLID"))
        return "fpmshell reads *ELEMENT_SOLID (8 nodes, of rigid parts) but not this form of it";
    if (starts_with(k, "ELEMENT_"))
        return "fpmshell models shells only (*ELEMENT_SHELL, and *ELEMENT_SOLID of rigid parts); "
               "this element kind would change the model";
    if (starts_with(k, "CONSTRAINED_"))
        return "this constraint is not supported (fpmshell reads "
               "*CONSTRAINED_NODAL_RIGID_BODY, *CONSTRAINED_SPOTWELD, "
               "*CONSTRAINED_GENERALIZED_WELD_SPOT, *CONSTRAINED_RIGID_BODIES and "
               "*CONSTRAINED_EXTRA_NODES), and ignoring it would change the model";
    if (starts_with(k, "BOUNDARY_PRESCRIBED_MOTION"))
        return "fpmshell reads *BOUNDARY_PRESCRIBED_MOTION_NODE, _SET and _RIGID (with _ID)";
    if (starts_with(k, "CONTACT_"))
        return "fpmshell reads *CONTACT_AUTOMATIC_SINGLE_SURFACE, _SURFACE_TO_SURFACE, "
               "_NODES_TO_SURFACE, _GENERAL, *CONTACT_SINGLE_SURFACE, _SURFACE_TO_SURFACE, "
               "_NODES_TO_SURFACE, *CONTACT_FORMING_ and *CONTACT_ERODING_SINGLE_SURFACE, "
               "_SURFACE_TO_SURFACE and _NODES_TO_SURFACE (as its shell self-contact), and "
               "*CONTACT_TIED_NODES_TO_SURFACE, _SHELL_EDGE_TO_SURFACE, _SURFACE_TO_SURFACE and "
               "*CONTACT_TIEBREAK_NODES_TO_SURFACE and _SURFACE_TO_SURFACE (other tiebreak forms "
               "are not supported)";
    if (starts_with(k, "INITIAL_"))
        return "fpmshell reads *INITIAL_VELOCITY (with NSIDEX), *INITIAL_VELOCITY_NODE, "
               "*INITIAL_VELOCITY_GENERATION and *INITIAL_VELOCITY_RIGID_BODY";
    if (starts_with(k, "LOAD_"))
        return "fpmshell reads *LOAD_NODE_POINT, *LOAD_NODE_SET, *LOAD_SHELL_SET, "
               "*LOAD_SEGMENT, *LOAD_SEGMENT_SET, *LOAD_BODY_X, _Y, _Z and *LOAD_BODY_PARTS";
    return "this card is not supported by fpmshell, and ignoring it could change the model";
}

void DeckTranslator::add(std::vector<Line>& out, const std::string& text, const Origin& at) {
    out.push_back({text, at});
}

DeckTranslation DeckTranslator::write() {
    write_segment_loads();
    write_body_loads();
    std::vector<Line> out;
    const Origin top{deck_.blocks.empty() ? nullptr : &deck_.blocks.front(), 0};
    const std::string title =
        title_.empty() ? std::filesystem::path(path_).stem().string() : title_;
    add(out, "title: " + yaml_name(title), top);
    add(out, "mesh: {file: " + yaml_name(mesh_file_) + "}", top);
    write_sets(out);
    write_list(out, "moves", moves_);
    write_materials(out);
    write_sections(out);
    write_curves(out);
    write_list(out, "boundary", boundary_);
    write_list(out, "loads", loads_);
    std::vector<Line> initial = initial_sets_;  // the more specific cards later (they win)
    initial.insert(initial.end(), initial_generated_.begin(), initial_generated_.end());
    initial.insert(initial.end(), initial_nodes_.begin(), initial_nodes_.end());
    initial.insert(initial.end(), initial_bodies_.begin(), initial_bodies_.end());
    write_list(out, "initial_conditions", initial);
    write_list(out, "masses", masses_);
    write_list(out, "constraints", constraints_);
    write_walls(out);
    write_list(out, "contact", contact_);
    if (damping_) out.push_back(*damping_);
    write_control(out);
    write_output(out);

    DeckTranslation t;
    for (const Line& l : out) {
        t.yaml += l.text + "\n";
        t.origins.push_back(l.at.block == nullptr ? SourceLine{path_, 0, ""}
                                                  : SourceLine{l.at.block->file, l.at.line,
                                                               "*" + l.at.block->keyword});
    }
    if (quadrangles_ > 0)
        note(*first_quadrangle_.block, first_quadrangle_.line,
             fmt::format("{} quadrangles split into two triangles each (along the shorter "
                         "diagonal): {} triangles in all",
                         quadrangles_, total_triangles()));
    t.notes = std::move(notes_);
    return t;
}

void DeckTranslator::write_list(std::vector<Line>& out, const char* key,
                                const std::vector<Line>& items) {
    if (items.empty()) return;
    add(out, std::string(key) + ":", items.front().at);
    out.insert(out.end(), items.begin(), items.end());
}

void DeckTranslator::write_sets(std::vector<Line>& out) {
    for (const auto& [id, at] : history_nodes_) {
        auto& g = node_groups_["node_" + std::to_string(id)];
        if (g.ids.empty()) {
            g.at = at;
            g.ids.push_back(id);
        }
    }
    if (node_groups_.empty() && element_groups_.empty()) return;
    add(out, "sets:",
        node_groups_.empty() ? element_groups_.begin()->second.at
                             : node_groups_.begin()->second.at);
    for (const auto* groups : {&node_groups_, &element_groups_})
        for (const auto& [name, g] : *groups) {
            std::string ids;
            for (const long long id : g.ids) ids += (ids.empty() ? "" : ", ") + std::to_string(id);
            add(out,
                "  " + yaml_name(name) +
                    (groups == &node_groups_ ? ": {node_ids: [" : ": {element_ids: [") + ids + "]}",
                g.at);
        }
}

long long DeckTranslator::total_triangles() const {
    long long shells = 0;
    for (const auto& [pid, p] : element_parts_) shells += p.count;
    return shells + quadrangles_;
}

}  // namespace fpmshell::deck
