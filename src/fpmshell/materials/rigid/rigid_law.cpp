#include "fpmshell/materials/rigid/rigid_law.hpp"

#include <string>
#include <utility>

#include "fpmshell/io/lsdyna/deck_material_card.hpp"
#include "fpmshell/io/model_blocks.hpp"
#include "fpmshell/materials/elastic/elastic_law.hpp"

namespace fpmshell {

namespace {

/// `fix`: the body's velocity components held at zero (model.hpp Material::rigid_fixed).
void read_rigid(const YamlMap& keys, Material& m) {
    m.rigid = true;
    if (const auto fix = keys.find("fix")) m.rigid_fixed = fixed_dofs(*fix);
}

/// *MAT_RIGID: MID, RO, E, PR, N, COUPLE, M, ALIAS; CMO, CON1, CON2.
void mat_rigid(deck::MaterialCard& card) {
    // a part of it moves as one rigid body (its section's particles, theory.md §6.11)
    const deck::Card f = card.required(0, "MID, RO, E, PR, N, COUPLE, M, ALIAS");
    const deck::Card g = card.optional(1);
    card.id(f);
    card.key("type: rigid");
    card.elastic(f, f.real(2, "E"), f.real(3, "PR"));
    const long long cmo = g.id(0, "CMO");
    if (cmo == -1)
        g.fail(
            "CMO -1: constraints in a local coordinate system are not supported (CMO 1 "
            "constrains the global directions)");
    if (cmo != 0 && cmo != 1) g.fail("CMO must be 0, 1 or -1");
    if (cmo != 1) return;
    // CON1, CON2: 1 x, 2 y, 3 z, 4 x y, 5 y z, 6 z x, 7 all
    static const char* const axes[8] = {"", "x", "y", "z", "xy", "yz", "zx", "xyz"};
    std::string fix;
    for (const auto& [field, prefix] : {std::pair{1, 'u'}, std::pair{2, 'r'}}) {
        const long long code = g.id(static_cast<std::size_t>(field), field == 1 ? "CON1" : "CON2");
        if (code < 0 || code > 7)
            g.fail(std::string(field == 1 ? "CON1" : "CON2") + " must be 0 to 7");
        for (const char* a = axes[code]; *a != '\0'; ++a)
            fix += (fix.empty() ? "" : ", ") + std::string{prefix, *a};
    }
    if (!fix.empty()) card.key("fix: [" + fix + "]");
}

}  // namespace

MaterialLaw rigid_law() {
    return {"rigid",
            false,
            {"fix"},
            read_rigid,
            make_elastic_group,
            {{{"MAT_RIGID", "MAT_020"}, mat_rigid}}};
}

}  // namespace fpmshell
