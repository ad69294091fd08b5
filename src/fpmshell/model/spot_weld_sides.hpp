// The force a spot weld carries (theory.md eq. 6.11-13). A weld is a rigid group of two
// particles a and b merged into a body; the rigid projection gives each particle of the body a
// constraint force f_p and no more: the force b's side exerts on a's side through the weld is
// the sum of f_p over a's side, the particles the body keeps joined to a once the weld is cut.
// That needs the weld to be the body's only link between a and b (a bridge of the body's
// graph); a weld whose particles are joined also through other groups carries an undetermined
// share of the force, and its failure is refused. A generalized weld (a group of more than two
// particles) carries onto each particle's side the sum of f_p over that side; its sides must be
// apart likewise.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct SpotWeldSide {
    std::size_t entry = 0;  ///< its entry of Model::nodal_rigid_bodies
    /// A weld of two particles: the particles whose constraint forces sum to the weld's force.
    std::vector<Index> side;
    /// +1: the sum is the force on the first particle's side; -1: on the second particle's
    /// side (the first's is its negative). The side summed holds no rigid material's particle
    /// where one side does (a held or driven part takes reactions the weld does not carry).
    Real sign = 1;
    /// A generalized weld (more than two particles): per particle of the group, in its order,
    /// its side (the particles the body keeps joined to it once the group is cut).
    std::vector<std::vector<Index>> node_sides{};
    /// The particle whose side holds a rigid material's particle (its force is the negative of
    /// the others' sum, for the reason above), -1 if none does.
    std::ptrdiff_t derived = -1;
};

struct SpotWeldSides {
    std::vector<SpotWeldSide> welds;  ///< the welds that can fail and have not, in entry order
    /// the first weld that is not its body's only link between its particles: its entry, why
    std::optional<std::pair<std::size_t, std::string>> problem;
};

/// `let_go`: per entry, nonzero for a weld that has failed (left out); empty: none has.
[[nodiscard]] SpotWeldSides spot_weld_sides(const Model& model,
                                            const std::vector<std::uint8_t>& let_go = {});

}  // namespace fpmshell
