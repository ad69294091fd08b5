// The translator of an LS-DYNA deck into the YAML model (io/lsdyna_deck.hpp). The deck is
// read whole first (mesh/keyword_deck.hpp: every *INCLUDE followed, every *PARAMETER known);
// then the cards that define what others refer to (parts, sections, materials, curves, tables,
// sets, shells) are read, and then every other card: a card may refer to anything the deck
// defines, before or after it, in any file (LS-DYNA reads a deck as a whole). The cards of
// the second pass are taken in an order of their own text, not of their place, so that a deck
// whose cards are reordered or spread over other files gives the same model.
//
// One file per card family, each reading its cards into the definitions below and writing its
// part of the model: deck_mesh_cards (shells, sets, segments), deck_materials (parts,
// sections, materials, curves, tables), deck_conditions (constraints on nodes, loads, initial
// velocities), deck_bodies (rigid walls, contacts, rigid-body constraints and welds),
// deck_controls (control and output cards); deck_translator.cpp holds the table from keyword
// to reader, the two passes and the model's layout.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fpmshell/io/lsdyna/deck_card.hpp"
#include "fpmshell/io/lsdyna_deck.hpp"

namespace fpmshell::deck {

struct Origin {
    const DeckBlock* block = nullptr;
    int line = 0;
};

struct Point2 {
    Real x = 0, y = 0;
};

struct CurveDef {
    Origin at;
    std::vector<Point2> points;  ///< scaled and offset
};

struct TableDef {
    Origin at;
    std::vector<Real> values;       ///< strain rates
    std::vector<long long> curves;  ///< the curve of each value
};

struct MaterialDef {
    Origin at;
    long long id = 0;  ///< MID
    std::string keyword;
    std::vector<std::string> keys;  ///< "type: elastic", "density: 7850", ... (flow curves later)
    long long lcss = 0;             ///< *MAT_024: the curve or table of the flow stress
    long long lcsr = 0;             ///< *MAT_024: the curve of the yield stress's rate factor
    bool plastic = false;
    /// its failure criteria ("plastic_strain: 0.2", ...) and what erodes an element ("points:
    /// 3", "layer_fraction: 0.5", "" for the default), written as one `failure` key
    std::vector<std::string> failure{};
    std::string failure_points{};
    /// *MAT_224: the curves of its failure strain against triaxiality (LCF), its factors against
    /// the plastic strain rate (LCG) and the element size (LCI); 0 none
    long long failure_curve = 0, failure_rate_curve = 0, failure_size_curve = 0;
};

struct SectionDef {
    Origin at;
    Real thickness = 0;
    int points = 2;           ///< NIP
    long long user_rule = 0;  ///< |QR| of a QR < 0: the IRID of an *INTEGRATION_SHELL; 0 none
    Real area_mass = 0;       ///< MAREA: non-structural mass per unit area
};

/// *INTEGRATION_SHELL: (S, WF) per point, the weights fractions of the thickness summing to 1.
struct IntegrationRuleDef {
    Origin at;
    std::vector<std::pair<Real, Real>> points;
};

/// The elements of one part: where the first is, how many, the thicknesses they give.
struct ElementPartInfo {
    Origin first;
    long long count = 0;
    std::set<Real> thickness;
};

/// A local coordinate system: its unit axes x, y, z in global components (from_nodes: a
/// *DEFINE_COORDINATE_NODES system, whose axes need node positions).
struct CoordinateSystemDef {
    Origin at;
    std::array<std::array<Real, 3>, 3> axes{};
    bool from_nodes = false;
};

struct PartDef {
    Origin at;
    long long section = 0, material = 0;
    /// *PART_INERTIA: the section's `inertia: {...}` key, and where the card is ("" none)
    std::string inertia{};
    Origin inertia_at{};
};

struct Segment {
    std::array<long long, 4> nodes{};  ///< N1 ... N4 (N4 = N3 or 0 for a triangle)
    Origin at;
};

struct SegmentLoad {
    std::string name;  ///< the segment set, or a name for a *LOAD_SEGMENT card
    std::vector<Segment> segments;
    Real sf = 1;
    std::string curve;
    Origin at;
    std::size_t slot = 0;  ///< its place among the loads (loads add up in the deck's order)
    /// a blast's keys after `elements` (*LOAD_BLAST_SEGMENT, deck_blast.cpp); "": a pressure
    std::string blast;
};

struct WallDef {
    Origin at;
    long long id = 0;
    std::string nodes;             ///< node set, "" for all
    std::string except_nodes;      ///< NSIDEX: a node set the wall does not act on, "" none
    std::array<Real, 3> normal{};  ///< a planar wall's head - tail (a moving one moves along it)
    Real mass = 0, speed = 0;      ///< moving walls: mass and the speed along the normal
    bool moving = false;
    Real friction = 0;  ///< a planar wall's FRIC: 0 frictionless, (0, 1) Coulomb, 1 no sliding
    /// the shape's keys of the model (model-format.md rigid_bodies): "shape: plane, point: ..."
    std::string geometry;
    /// a geometric wall's _MOTION: its curve (0: none), OPT (0 velocity, 1 displacement), the
    /// direction cosines, and the card
    long long motion_curve = 0, motion_opt = 0;
    std::array<Real, 3> motion_dir{};
    Origin motion_at;
};

/// One line of the model file and the card it comes from.
struct Line {
    std::string text;
    Origin at;
};

class DeckTranslator {
public:
    DeckTranslator(const std::string& path, std::string mesh_file);

    /// Both passes over the deck's cards, then the model.
    DeckTranslation translate();

    /// Which pass reads a card: definitions first, then everything that refers to them.
    enum class Pass { Definitions, References };
    using Reader = void (DeckTranslator::*)(const DeckBlock&);

    // The readers of the card families and their helpers (the table from keyword to reader in
    // deck_translator.cpp names them).
    // ---- the passes, notes and the model's layout (deck_translator.cpp)
    void note(const DeckBlock& b, int line, const std::string& what);
    [[noreturn]] static void refuse(const DeckBlock& b, const std::string& why);
    /// Card k of the block; an optional card left out reads as blank fields.
    Card card(const DeckBlock& b, std::size_t k, const std::vector<std::size_t>& widths = k_ten);
    Card required_card(const DeckBlock& b, std::size_t k, const char* what,
                       const std::vector<std::size_t>& widths = k_ten);
    static std::string ignored_reason(const std::string& k);
    static std::string unsupported_reason(const std::string& k);
    void add(std::vector<Line>& out, const std::string& text, const Origin& at);
    DeckTranslation write();
    void write_list(std::vector<Line>& out, const char* key, const std::vector<Line>& items);
    void write_sets(std::vector<Line>& out);
    [[nodiscard]] long long total_triangles() const;
    void title(const DeckBlock& b);
    void mesh_only(const DeckBlock& b);
    void ignored(const DeckBlock& b);
    void unsupported(const DeckBlock& b);
    /// "FILE:LINE" of a card, for messages that name two places.
    static std::string place(const Origin& at);
    /// The place of block b among the blocks of its family in reading order (1, 2, ...):
    /// LS-DYNA numbers the rigid walls and contacts that carry no id by it.
    [[nodiscard]] long long reading_number(const DeckBlock& b) const;

    // ---- shells, sets and segments (deck_mesh_cards.cpp)
    void element_shell(const DeckBlock& b);
    /// *ELEMENT_SOLID: the parts of the solids (the mesh reader makes their outer faces).
    void element_solid(const DeckBlock& b);
    /// *ELEMENT_MASS, _NODE_SET, _PART, _PART_SET: lumped masses (deck_masses.cpp).
    void element_mass(const DeckBlock& b);
    void part_mass(const DeckBlock& b, const std::set<std::string>& opt);
    void set_header(const DeckBlock& b);
    /// The name of set `sid` of `kind` (node, shell, part), which the deck must define.
    std::string set_name(const Card& f, const std::string& kind, long long sid) const;
    void define_set(const Card& f, const std::string& kind, long long sid, const std::string& name);
    /// *SET_SEGMENT(_TITLE): a header card (SID), then one card per segment (N1 ... N4).
    void segment_set(const DeckBlock& b);
    /// The segment of nodes in fields first ... first + 3 of `f`.
    static Segment segment(const Card& f, std::size_t first, const DeckBlock& b);
    /// The element sets and pressures of the segment loads: each segment's shell (the one with
    /// its nodes), in a set of the shells whose normal the segment's node order follows and one
    /// (`<name>_reversed`, the pressure negated) of those it opposes.
    void write_segment_loads();
    /// The distinct node numbers of a shell or segment, sorted (a triangle's fourth is 0).
    static std::array<long long, 4> node_key(const std::array<long long, 4>& n);
    /// Whether segment s runs round its shell in the shell's own direction.
    static bool same_order(const std::array<long long, 4>& shell,
                           const std::array<long long, 4>& s);

    // ---- parts, sections, materials, curves and tables (deck_materials.cpp)
    /// Parts: a heading card and a data card each (one *PART may define several).
    void part(const DeckBlock& b);
    /// *PART_INERTIA: a rigid part's mass, centre and inertia tensor (IRCS 0, XC..ZC), and its
    /// initial velocity VTX..VRZ.
    void part_inertia(const DeckBlock& b);
    /// *PART_MOVE: a part or part set translated before the run (`moves`).
    void part_move(const DeckBlock& b);
    /// The `inertia: {...}` key of a part of *PART_INERTIA, "" for another (refused where the
    /// part's material is not *MAT_RIGID).
    std::string given_inertia(const PartDef& part, const MaterialDef& m);
    void section_shell(const DeckBlock& b);
    /// *SECTION_SOLID: read for the parts of *MAT_RIGID only (their solids are a rigid body).
    void section_solid(const DeckBlock& b);
    /// The `sections` entry of a part meshed with solids: a rigid material, its outer faces
    /// without thickness, its inertia that of the solid they enclose.
    void write_solid_section(std::vector<Line>& out, long long pid, const ElementPartInfo& e,
                             bool& first);
    void integration_shell(const DeckBlock& b);
    void material(const DeckBlock& b);
    /// A *MAT_ADD_ card: the failure criterion whose deck cards hold it
    /// (failure/failure_criteria.cpp) translates it.
    void add_failure_card(const DeckBlock& b);
    /// The material `mid` of the deck, nullptr if none.
    [[nodiscard]] MaterialDef* material_def(long long mid);
    /// The points of the *DEFINE_CURVE `id`, nullptr if none.
    [[nodiscard]] const std::vector<Point2>* curve_points(long long id) const;
    static std::string points_text(const std::vector<Point2>& points);
    void define_curve(const DeckBlock& b);
    void define_table(const DeckBlock& b);
    void write_materials(std::vector<Line>& out);
    /// The flow curve (or the curves per rate) of a *MAT_024's LCSS.
    std::string rate_scaling(const MaterialDef& m);
    std::string flow_curves(const MaterialDef& m);
    /// *MAT_224's failure curves as a `tabulated: {...}` criterion ("" for none).
    std::string failure_curves(const MaterialDef& m);
    void write_sections(std::vector<Line>& out);
    std::string thickness_rule_keys(const SectionDef& s, const MaterialDef& m, long long pid);
    void write_curves(std::vector<Line>& out);

    // ---- constraints on nodes, loads and initial velocities (deck_conditions.cpp)
    /// The id card of the _ID options (ID, HEADING) comes first.
    static std::size_t first_data_card(const std::set<std::string>& opt);
    void spc(const DeckBlock& b);
    /// *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET: a velocity (VAD 0) or a displacement (VAD 2)
    /// along x, y or z (DOF 1, 2, 3), the curve times SF; the node's other directions stay free.
    void prescribed_motion(const DeckBlock& b);
    void prescribed_rigid_motion(const DeckBlock& b, const std::set<std::string>& opt);
    static std::string replace_nodes(std::string text, const std::string& set);
    /// Node `id` joins the set `group` (of node_ids); the first node writes `text` (with NODES
    /// for the set's name) into `lines`.
    void add_node_to_group(const std::string& group, long long id, const std::string& text,
                           const Origin& at, std::vector<Line>& lines);
    std::string nodes_of_velocity(const Card& f, long long id, long long styp);
    void initial_velocity(const DeckBlock& b);
    /// "velocity: [VX, VY, VZ], angular_velocity: [VXR, VYR, VZR]" from fields first ...
    /// first + 5, given in the local system cid (0: global) and written in global components.
    std::string velocities(const Card& f, std::size_t first, long long cid = 0) const;
    /// *DEFINE_COORDINATE_SYSTEM / _VECTOR / _NODES (deck_coordinates.cpp).
    void define_coordinate(const DeckBlock& b);
    /// The global components of a vector given in the local system cid (0: global itself); a
    /// system that is not defined, or is of _NODES, is an error at card f.
    [[nodiscard]] std::array<Real, 3> to_global(const Card& f, long long cid,
                                                const std::array<Real, 3>& local) const;
    /// The model's name of load curve `lcid` (written out if some card uses it).
    std::string curve_ref(const DeckBlock& b, const Card& f, long long lcid);
    void load(const DeckBlock& b);
    /// *LOAD_SEGMENT_SET (SSID, LCID, SF, AT) and *LOAD_SEGMENT (LCID, SF, AT, N1 ... N4): a
    /// pressure along each segment's normal (by its node order), on the shell it covers.
    void segment_load(const DeckBlock& b);
    /// *LOAD_BODY_X, _Y, _Z (gravity: a base acceleration, its pull the other way) and
    /// *LOAD_BODY_PARTS (the parts they load); written once the deck is read.
    void body_load(const DeckBlock& b);
    void write_body_loads();
    /// *LOAD_BLAST_ENHANCED and *LOAD_BLAST_SEGMENT(_SET) (deck_blast.cpp).
    void blast_source(const DeckBlock& b);
    void blast_segment_load(const DeckBlock& b);

    // ---- rigid walls, contacts, rigid-body constraints and welds (deck_bodies.cpp)
    /// *CONSTRAINED_NODAL_RIGID_BODY (_TITLE): the nodes of NSID move as one rigid body.
    void nodal_rigid_body(const DeckBlock& b);
    void rigid_bodies_joined(const DeckBlock& b);
    void extra_nodes(const DeckBlock& b);
    void require_rigid_part(const Card& f, long long pid, const char* what);
    // ---- spot welds (deck_welds.cpp)
    /// *CONSTRAINED_SPOTWELD (_ID): each weld's two nodes move as one rigid body until the
    /// weld fails by SN, SS (N, M), TF (theory.md eq. 6.11-13) or EP (eq. 6.11-15).
    void spot_weld(const DeckBlock& b);
    /// *CONSTRAINED_GENERALIZED_WELD_SPOT (_ID): the nodes of NSID move as one rigid body; a
    /// weld of two nodes fails as a spot weld does (TFAIL, SN, SS, N, M, EPSF).
    void generalized_spot_weld(const DeckBlock& b);
    /// The `failure` keys of a weld card: SN at field `sn` (SS, N, M after it), TF at `tf`,
    /// the plastic strain at `ep` (named `ep_name`); `defaulted` set where a blank exponent is
    /// taken as 2.
    std::string weld_failure(const Card& f, std::size_t sn, std::size_t tf, std::size_t ep,
                             const char* ep_name, bool& defaulted);
    void rigid_wall(const DeckBlock& b);
    void add_wall(const WallDef& w, const Card& f);
    static std::array<Real, 3> unit(const std::array<Real, 3>& v);
    static std::string unit_text(const std::array<Real, 3>& v);
    /// *RIGIDWALL_GEOMETRIC_FLAT (a rectangle), _CYLINDER, _SPHERE: a fixed rigid body of that
    /// shape (model/rigid_face.hpp) the nodes stay outside of; _ID and _DISPLAY (its card
    /// skipped) read, _MOTION refused.
    void geometric_wall(const DeckBlock& b);
    /// *CONTACT_AUTOMATIC_SINGLE_SURFACE: self-contact over its side; _SURFACE_TO_SURFACE and
    /// _NODES_TO_SURFACE: self-contact over the union of both sides, which keeps the two
    /// apart (and each side from itself too: noted).
    void contact(const DeckBlock& b);
    /// The element set of one side of a contact: SID of type TYP (1 shell set, 2 part set,
    /// 3 part, 5 all; SID 0 is all).
    void tied_contact(const DeckBlock& b);
    std::string contact_friction(const Card& g);
    /// The fourth card of a *CONTACT_ERODING_ form (ISYM, EROSOP, IADJ), at `index`: checked
    /// and noted (fpmshell's self-contact erodes already).
    void eroding_contact_card(const DeckBlock& b, std::size_t index);
    std::string contact_side(const Card& f, long long sid, long long typ, const char* name);
    void write_walls(std::vector<Line>& out);
    /// The constant velocity of a geometric wall's _MOTION: a flat velocity curve (OPT 0) or a
    /// straight displacement curve from 0 at t = 0 (OPT 1), along the direction; fpmshell's
    /// fixed bodies move at a constant velocity, so any other curve is refused.
    std::string wall_velocity(const WallDef& w);

    // ---- control and output cards (deck_controls.cpp)
    void control(const DeckBlock& b);
    void database(const DeckBlock& b);
    void write_control(std::vector<Line>& out);
    void write_output(std::vector<Line>& out);

private:
    using ElementPart = ElementPartInfo;
    struct NodeGroup {
        Origin at;
        std::vector<long long> ids;
    };

    std::string path_, mesh_file_;
    KeywordDeck deck_;
    std::vector<std::string> notes_;
    std::string title_;
    std::map<long long, ElementPart> element_parts_;
    std::map<long long, ElementPart> solid_parts_;  ///< parts of *ELEMENT_SOLID
    std::map<long long, Origin> solid_sections_;    ///< *SECTION_SOLID by SECID
    long long quadrangles_ = 0;
    Origin first_quadrangle_;
    std::map<std::string, std::map<long long, std::string>> set_names_;
    std::map<long long, PartDef> parts_;
    std::map<long long, SectionDef> sections_;
    std::map<long long, CoordinateSystemDef> coordinate_systems_;
    std::map<long long, IntegrationRuleDef> integration_rules_;
    std::optional<Origin> lobatto_shells_;  ///< *CONTROL_SHELL INTGRD 1
    std::map<long long, MaterialDef> materials_;
    std::map<long long, CurveDef> curves_;
    std::map<long long, TableDef> tables_;
    long long last_table_ = 0;
    std::size_t table_waiting_ = 0;
    std::vector<std::pair<long long, Origin>> used_curves_;
    std::map<std::string, NodeGroup> node_groups_;
    std::map<std::string, NodeGroup> element_groups_;  // element sets by number (segment loads)
    struct Shell {
        long long id = 0;
        std::array<long long, 4> nodes{};
    };
    std::vector<Shell> shells_;  // every shell's number and nodes (for segments)
    std::map<std::string, std::vector<Segment>> segment_sets_;
    /// A contact's side given as a segment set (SSTYP or MSTYP 0): the element group `group`
    /// of the shells its segments cover, filled once every card is read.
    struct SegmentSide {
        std::string group;
        long long set_id = 0;
        Origin at;
    };
    std::vector<SegmentSide> segment_sides_;
    std::vector<SegmentLoad> segment_loads_;
    /// *LOAD_BODY_X, _Y, _Z: its place among the loads (filled by write_body_loads) and text
    /// without the parts; *LOAD_BODY_PARTS: the part set's name and card
    std::vector<std::pair<std::size_t, std::string>> body_loads_;
    std::optional<std::pair<std::string, Origin>> body_parts_;
    std::map<long long, std::pair<std::string, Origin>> blast_sources_;  ///< BID: its keys
    /// the model line of a load or prescribed motion on single nodes -> the set of its nodes
    std::map<std::string, std::string> node_group_of_text_;
    std::vector<Line> boundary_, loads_, contact_, control_, constraints_;
    std::vector<Line> moves_;   ///< *PART_MOVE
    std::vector<Line> masses_;  ///< *ELEMENT_MASS, _NODE_SET
    /// initial velocities of *INITIAL_VELOCITY, _GENERATION and _NODE, written in that order
    std::vector<Line> initial_sets_, initial_generated_, initial_nodes_;
    std::vector<Line> initial_bodies_;  ///< of *PART_INERTIA: written last (they win)
    long long welds_ = 0;               ///< spot welds read (their sets are numbered by it)
    std::vector<WallDef> walls_;
    std::optional<Line> end_time_, damping_, every_, fields_every_;
    std::optional<Line> min_step_factor_;  ///< *CONTROL_TERMINATION DTMIN > 0
    bool erode_shells_ = false;            ///< *CONTROL_TIMESTEP ERODE 10, 11, 110, 111
    Real every_value_ = 0;
    long long fields_every_npltc_ = 0;
    bool wall_forces_ = false;
    bool contact_forces_ = false;  ///< *DATABASE_RCFORC: a history of each contact's force
    std::optional<Origin> part_velocities_;  ///< *DATABASE_MATSUM: each part's momentum velocity
    std::vector<std::pair<long long, Origin>> contact_ids_;  ///< per contact card: its number
    std::vector<std::pair<long long, Origin>> history_nodes_;
    std::map<const DeckBlock*, long long> reading_numbers_;
    std::map<std::string, std::map<long long, Origin>> set_places_;  ///< kind -> id -> card
};

}  // namespace fpmshell::deck
