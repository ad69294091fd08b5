// YAML model file -> validated Model (see model_reader.hpp and model-format.md): the file is
// loaded, the --set overrides applied, and the blocks read in the order in which they depend on
// each other (model_blocks.hpp); the checks that span blocks are here.
#include "fpmshell/io/model_reader.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/mesh_input.hpp"
#include "fpmshell/io/model_blocks.hpp"
#include "fpmshell/io/overrides.hpp"
#include "fpmshell/io/set_builder.hpp"
#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/model/rigid_body_partition.hpp"
#include "fpmshell/model/spot_weld_sides.hpp"

namespace fpmshell {
namespace {

constexpr std::uintmax_t k_max_model_file_bytes = 64U << 20U;

const std::vector<std::string> k_top_keys = {"title",       "mesh",         "sets",
                                             "materials",   "sections",     "boundary",
                                             "curves",      "loads",        "initial_conditions",
                                             "constraints", "rigid_bodies", "contact",
                                             "damping",     "control",      "output",
                                             "moves",       "masses"};

YAML::Node load_yaml(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw InputError(input_error_text(path, 0, "",
                                          "cannot open the model file: it is a "
                                          "folder; expected a YAML file"));
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(input_error_text(
            path, 0, "", std::string("cannot open the model file (") + std::strerror(errno) + ")"));
    // Read at most the limit (+1 byte to notice more): also safe on pipes and devices.
    std::string content;
    std::vector<char> chunk(1U << 16U);
    while (in && content.size() <= k_max_model_file_bytes) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        content.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (content.size() > k_max_model_file_bytes)
        throw InputError(input_error_text(path, 0, "",
                                          "the model file is larger than 64 MiB; "
                                          "put big data in a mesh file"));
    try {
        return YAML::Load(content);
    } catch (const YAML::Exception& e) {
        const int line = e.mark.is_null() ? 0 : e.mark.line + 1;
        throw InputError(input_error_text(path, line, "",
                                          "the file is not valid YAML (" + e.msg +
                                              "); check the indentation, colons, quotes and "
                                              "brackets on this line and the lines just before"));
    }
}

/// A particle of no shell element (a node its mesh file gives a point mass, LS-DYNA's
/// *ELEMENT_MASS) must carry a point mass of `masses`: without mass it could not move.
void check_every_particle_has_mass(const YamlMap& top, const Model& model) {
    std::vector<std::uint8_t> carried(model.nodes.size(), 0);
    for (const auto& t : model.triangles)
        for (const Index p : t) carried[static_cast<std::size_t>(p)] = 1;
    for (const PointMass& m : model.point_masses)
        for (const Index p : m.nodes) carried[static_cast<std::size_t>(p)] = 1;
    for (std::size_t p = 0; p < carried.size(); ++p)
        if (!carried[p]) {
            const Vec3& x = model.nodes[p];
            top.at("mesh").fail(fmt::format(
                "particle {} at ({:g}, {:g}, {:g}) belongs to no shell element and no entry of "
                "`masses` gives it a mass: it could not move",
                p + 1, x.x(), x.y(), x.z()));
        }
}

/// The model of the tree `root`: `path` names the model (its title by default, messages),
/// mesh files are relative to `base_dir`.
Model read_model_tree(YamlContext& ctx, YAML::Node root, const std::string& path,
                      const std::string& base_dir, const std::vector<std::string>& set_overrides) {
    if (!root.IsDefined() || root.IsNull())
        throw InputError(input_error_text(path, 0, "",
                                          "the model file is empty; expected a map "
                                          "with at least mesh, materials, sections "
                                          "and control"));
    if (!root.IsMap())
        throw InputError(input_error_text(
            path, yaml_line(root), "",
            std::string("the top level of the model file must be a map of keys (title, mesh, "
                        "materials, ...), got ") +
                (root.IsSequence() ? "a list" : "a single value")));
    apply_overrides(root, set_overrides, ctx);

    Model model;
    model.source_file = path;
    const YamlMap top = YamlValue(ctx, root, "").map(k_top_keys);
    for (const char* required : {"mesh", "materials", "sections", "control"})
        if (!top.has(required))
            ctx.fail_at(1, required,
                        "is required but missing; a model needs mesh, materials, "
                        "sections and control");

    model.title = std::filesystem::path(path).stem().string();
    if (const auto t = top.find("title")) model.title = t->name();

    read_control(top.at("control"), model);

    // Mesh and sets.
    const YamlValue mesh_key = top.at("mesh");
    MeshData mesh = read_mesh_block(mesh_key, base_dir);
    if (mesh.node_sets.count("all") != 0 || mesh.element_sets.count("all") != 0)
        mesh_key.fail(
            "the mesh defines a set named 'all', which is reserved for the set of every "
            "node and element; rename it in the mesh file");
    if (const auto s = top.find("sets")) add_user_sets(*s, mesh);
    model.notes.insert(model.notes.end(), mesh.notes.begin(), mesh.notes.end());
    model.nodes = std::move(mesh.nodes);
    model.triangles = std::move(mesh.triangles);
    model.node_sets = std::move(mesh.node_sets);
    model.element_sets = std::move(mesh.element_sets);
    for (auto* sets : {&model.node_sets, &model.element_sets})
        for (auto& [name, members] : *sets) {
            std::sort(members.begin(), members.end());
            members.erase(std::unique(members.begin(), members.end()), members.end());
        }
    auto& all_nodes = model.node_sets["all"];
    for (Index i = 0; i < model.n_particles(); ++i) all_nodes.push_back(i);
    auto& all_elements = model.element_sets["all"];
    for (Index e = 0; e < model.n_elements(); ++e) all_elements.push_back(e);

    // the parts moved into place before anything reads the geometry (sets by position were
    // taken on the mesh as read)
    if (const auto mv = top.find("moves")) read_moves(*mv, model);
    read_materials(top.at("materials"), model);
    if (const auto c = top.find("curves")) read_curves(*c, model);
    read_sections(top.at("sections"), model);
    if (model.control.mode == SolutionMode::Relaxation) {
        // Dynamic relaxation jumps to each load level and oscillates about it: an elastic model
        // ends where it should, a plastic one keeps the plastic strain of the overshoot and of
        // the motion imposed in one step (a strip pulled in tension: 11 % of the right force).
        for (const Section& sec : model.sections) {
            const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
            if (mat.plastic())
                top.at("control")
                    .open_map("control settings")
                    .at("mode")
                    .fail(
                        "relaxation needs elastic materials, but material '" + mat.name +
                        "' is plastic: dynamic relaxation jumps to each load level, and a plastic "
                        "material would keep the strains of that jump; use mode: dynamic with a "
                        "slow "
                        "load ramp (and some mass damping) for a quasi-static plastic path");
        }
    }
    if (model.control.membrane == MembraneKernel::Smoothed)
        for (const Section& sec : model.sections)  // §3.5 averages over the neighbours
            if (const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
                mat.failure.active())
                top.at("control")
                    .open_map("control settings")
                    .at("membrane")
                    .fail(
                        "the smoothed membrane averages each element's strain with its "
                        "neighbours', which erosion would take away: material '" +
                        mat.name + "' can fail, so use membrane: cst");
    if (const auto b = top.find("boundary")) read_boundary(*b, model);
    if (const auto l = top.find("loads")) read_loads(*l, model);
    if (const auto i = top.find("initial_conditions")) read_initial_conditions(*i, model);
    add_area_masses(model);
    if (const auto pm = top.find("masses")) read_point_masses(*pm, model);
    check_every_particle_has_mass(top, model);
    if (const auto c = top.find("constraints"); c && !c->is_null()) {
        read_constraints(*c, model);
        // a weld that can fail must be its body's only link between its particles (eq. 6.11-13)
        if (const auto problem = spot_weld_sides(model).problem) {
            std::size_t rigid = 0;  // the entry among those of type rigid
            for (const YamlValue& item : c->list("constraints"))
                if (item.open_map("a constraint").at("type").text() == "rigid" &&
                    rigid++ == problem->first)
                    item.fail(problem->second);
        }
    }
    // the entries of type rigid_body on the rigid bodies the sections and constraints make
    if (const auto b = top.find("boundary"))
        if (const auto problem = rigid_body_partition(model).problem)
            b->list("boundary conditions")[problem->first].fail(problem->second);
    if (const auto r = top.find("rigid_bodies"); r && !r->is_null()) read_rigid_bodies(*r, model);
    read_end_when_body_stops(top.at("control"), model);
    if (const auto c = top.find("contact"); c && !c->is_null()) {
        read_contact(*c, model);
        if (model.control.mode == SolutionMode::Relaxation && !model.contacts.empty())
            c->fail(
                "contact needs mode: dynamic (dynamic relaxation jumps between load levels, "
                "and the contact forces of a jump are not those of equilibrium)");
    }
    if (const auto d = top.find("damping")) read_damping(*d, model);
    read_output(top.find("output"), model);
    return model;
}

}  // namespace

Model read_model(const std::string& path, const std::vector<std::string>& set_overrides) {
    YamlContext ctx(path);
    YAML::Node root = load_yaml(path);
    return read_model_tree(ctx, root, path, std::filesystem::path(path).parent_path().string(),
                           set_overrides);
}

Model read_model_text(const std::string& yaml, std::vector<SourceLine> origins,
                      const std::string& source, const std::vector<std::string>& set_overrides) {
    YamlContext ctx(source);
    ctx.set_line_origins(std::move(origins));
    YAML::Node root;
    try {
        root = YAML::Load(yaml);
    } catch (const YAML::Exception& e) {
        throw InputError(input_error_text(
            source, 0, "",
            "the translated model is not valid YAML (" + e.msg + "); please report this deck"));
    }
    return read_model_tree(ctx, root, source, std::filesystem::path(source).parent_path().string(),
                           set_overrides);
}

}  // namespace fpmshell
