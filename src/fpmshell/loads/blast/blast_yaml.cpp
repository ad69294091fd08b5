#include "fpmshell/loads/blast/blast_yaml.hpp"

#include "fpmshell/io/model_names.hpp"

namespace fpmshell {

BlastLoad read_blast_load(const YamlValue& item, const Model& model) {
    const YamlMap m =
        item.map({"type", "elements", "charge_mass", "centre", "burst", "detonation_time",
                  "death_time", "scale", "units", "reversed", "negative_phase"});
    if (model.control.mode == SolutionMode::Relaxation)
        m.at("type").fail(
            "a blast needs mode: dynamic (its shock is a pulse in time; dynamic relaxation "
            "runs through load levels in a fictitious time)");
    BlastLoad b;
    b.elements = named_element_set(model, m.at("elements", "an element set name"));
    b.charge_mass =
        m.at("charge_mass", "the charge's TNT-equivalent mass, a number > 0").positive();
    const YamlValue centre =
        m.at("centre", "[x, y, z], or the name of a node set of one node (its initial position)");
    if (centre.is_scalar()) {
        const std::vector<Index>& nodes = named_node_set(model, centre);
        if (nodes.size() != 1)
            centre.fail("the charge's centre: a node set of one node (this one has " +
                        std::to_string(nodes.size()) + ")");
        b.centre = model.nodes[static_cast<std::size_t>(nodes[0])];
    } else {
        b.centre = centre.vec3();
    }
    if (const auto burst = m.find("burst"))
        b.burst = burst->choice({"free_air", "surface"}) == "free_air" ? BlastBurst::FreeAir
                                                                       : BlastBurst::Surface;
    b.detonation_time = m.real_or("detonation_time", 0.0);
    b.death_time = m.positive_or("death_time", b.death_time);
    b.scale = m.positive_or("scale", 1.0);
    b.reversed = m.choice_or("reversed", {"true", "false"}, "false") == "true";
    b.negative_phase = m.choice_or("negative_phase", {"true", "false"}, "false") == "true";
    if (const auto units = m.find("units")) {
        const YamlMap u = units->map({"length", "mass", "time"});
        b.metres = u.positive_or("length", 1.0);
        b.kilograms = u.positive_or("mass", 1.0);
        b.seconds = u.positive_or("time", 1.0);
    }
    return b;
}

}  // namespace fpmshell
