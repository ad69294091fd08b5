// The fields of the VTU frames (model-format.md "Results in DIR", VTU point and cell data),
// each declared once: its name, its number of components, whether it lives on the particles or
// on the triangles, and how its values come from the model and the solver state. A frame holds
// the fields of the list in list order; a new field is one more entry in standard_fields(model).
#pragma once

#include <array>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/io/field_frame.hpp"

namespace fpmshell {

class ExplicitSolver;
class ShellElements;
struct Model;

enum class FieldLocation { Point, Cell };

/// What a field is computed from.
struct FieldSource {
    const Model& model;
    const ExplicitSolver& solver;
    /// The particle positions the frame shows: the solver's, or the last good ones of a run
    /// that failed.
    const std::vector<Vec3>& positions;
};

struct OutputField {
    /// Writes the values of the particles (Point) or triangles (Cell) `items` to `out`, item
    /// after item, `components` values each.
    using Values = std::function<void(const FieldSource& source, std::span<const Index> items,
                                      std::span<Real> out)>;

    std::string name;  ///< the array name in the .vtu file
    int components = 1;
    FieldLocation location = FieldLocation::Point;
    Values values;
};

/// The fields of every frame, in the order they appear in the .vtu files: point data
/// displacement, velocity, rotation; cell data membrane_force, bending_moment, thickness,
/// plastic_strain_top, plastic_strain_middle, plastic_strain_bottom; where a material of the
/// model can fail, then `eroded` (1 on an eroded element, 0 elsewhere; theory.md §7.6).
[[nodiscard]] std::vector<OutputField> standard_fields(const Model& model);

/// The frame at `time`: the source's positions, the model's triangles and one array per field.
[[nodiscard]] FieldFrame field_frame(const std::vector<OutputField>& fields,
                                     const FieldSource& source, Real time);
/// The same into `frame`, whose vectors are reused: a run writes frames of one size again and
/// again, and fresh memory for each (150 MB for 10^6 triangles) costs more in page faults than
/// gathering the values. The items are gathered on the OpenMP threads.
void field_frame(const std::vector<OutputField>& fields, const FieldSource& source, Real time,
                 FieldFrame& frame);

/// The part of a frame that one rank of a distributed run writes (fields/frame_NNNNN_rankR.vtu):
/// the elements it computes and the particles of those elements (every one of them updated on
/// this rank: their state is that of a single-process run), with rank 0 also the particles of no
/// element; all in ascending order.
struct FramePiece {
    std::vector<Index> particles, elements;
    std::vector<std::array<Index, 3>> triangles;  ///< the elements' corners, indices into particles
};

/// The piece of `elements` (ascending): their particles, and with `lone_particles` also the
/// particles that no triangle of the model names.
[[nodiscard]] FramePiece frame_piece(const Model& model, std::vector<Index> elements,
                                     bool lone_particles);

/// The piece's frame: its particles and triangles, one array per field over its items, then
/// the point array `particle_index` and the cell array `element_index` (each item's index in
/// the single-process frame, from 0), so that the pieces of a frame join into it.
void field_frame(const std::vector<OutputField>& fields, const FieldSource& source, Real time,
                 const FramePiece& piece, FieldFrame& frame);

/// Surfaces of the shell at which the plastic strain is reported.
enum class ShellSurface { Bottom, Middle, Top };

/// Equivalent plastic strain of element e at a surface, averaged over its in-plane points; with
/// an even number of thickness points the middle is the mean of the bottom and top points.
[[nodiscard]] Real surface_plastic_strain(const ShellElements& elements, Index e,
                                          ShellSurface surface);

}  // namespace fpmshell
