// The field list of the VTU frames and the frame built from it.
#include "fpmshell/driver/output_fields.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

#include "fpmshell/core/rotation.hpp"
#include "fpmshell/failure/element_erosion.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

namespace {

std::size_t at(Index i) { return static_cast<std::size_t>(i); }

/// Items per call of a field's `values` in field_frame.
constexpr std::size_t k_items_per_range = 4096;

template <class Vector3>
void put3(Real* out, const Vector3& v) {
    for (int c = 0; c < 3; ++c) out[c] = v[c];
}

/// A field of 3 components, item by item from `of(source, item)`.
template <class Of>
OutputField::Values three_components(Of of) {
    return [of](const FieldSource& s, std::span<const Index> items, std::span<Real> out) {
        for (std::size_t k = 0; k < items.size(); ++k) put3(out.data() + 3 * k, of(s, items[k]));
    };
}

/// A field of 1 component, item by item from `of(source, item)`.
template <class Of>
OutputField::Values one_component(Of of) {
    return [of](const FieldSource& s, std::span<const Index> items, std::span<Real> out) {
        for (std::size_t k = 0; k < items.size(); ++k) out[k] = of(s, items[k]);
    };
}

/// A cell field of the plastic strain at one surface.
OutputField plastic_strain_field(std::string name, ShellSurface surface) {
    return {std::move(name), 1, FieldLocation::Cell,
            one_component([surface](const FieldSource& s, Index e) {
                return surface_plastic_strain(s.solver.elements(), e, surface);
            })};
}

/// The arrays of the fields over the frame's points and triangles: every particle and element of
/// the model (piece null), or the piece's.
void fill_frame(const std::vector<OutputField>& fields, const FieldSource& source,
                const FramePiece* piece, FieldFrame& frame) {
    std::size_t n_point_arrays = 0, n_cell_arrays = 0;
    for (const OutputField& field : fields)
        ++(field.location == FieldLocation::Point ? n_point_arrays : n_cell_arrays);
    frame.point_data.resize(n_point_arrays);
    frame.cell_data.resize(n_cell_arrays);
    std::size_t next_point_array = 0, next_cell_array = 0;
    for (const OutputField& field : fields) {
        const bool on_points = field.location == FieldLocation::Point;
        const std::size_t n = on_points ? frame.points.size() : frame.triangles.size();
        const Index* listed = piece == nullptr
                                  ? nullptr
                                  : (on_points ? piece->particles.data() : piece->elements.data());
        const std::size_t width = at(field.components);
        FieldArray& array =
            on_points ? frame.point_data[next_point_array++] : frame.cell_data[next_cell_array++];
        array.name = field.name;
        array.components = field.components;
        array.values.resize(n * width);
        Real* values = array.values.data();
        // Fixed ranges, each writing its own values: the same bytes on any number of threads;
        // one call of the field per range (a call per item cost as much as the values).
        const std::size_t n_ranges = (n + k_items_per_range - 1) / k_items_per_range;
#pragma omp parallel for schedule(static) if (n_ranges > 1)
        for (std::size_t r = 0; r < n_ranges; ++r) {
            const std::size_t first = r * k_items_per_range;
            const std::size_t last = std::min(n, first + k_items_per_range);
            std::array<Index, k_items_per_range> range;  // NOLINT: filled below
            for (std::size_t k = first; k < last; ++k)
                range[k - first] = listed != nullptr ? listed[k] : static_cast<Index>(k);
            field.values(source, std::span<const Index>(range.data(), last - first),
                         std::span<Real>(values + first * width, (last - first) * width));
        }
    }
}

}  // namespace

std::vector<OutputField> standard_fields(const Model& model) {
    using L = FieldLocation;
    std::vector<OutputField> fields{
        {"displacement", 3, L::Point, three_components([](const FieldSource& s, Index p) {
             return Vec3(s.positions[at(p)] - s.solver.state().x0[at(p)]);
         })},
        {"velocity", 3, L::Point,
         three_components([](const FieldSource& s, Index p) { return s.solver.state().v[at(p)]; })},
        {"rotation", 3, L::Point,  // rotation vector (theory.md §1.4)
         three_components([](const FieldSource& s, Index p) {
             return rotation_vector(s.solver.state().rotation[at(p)]);
         })},
        {"membrane_force", 3, L::Cell,  // xx, yy, xy per unit length, element frame
         three_components(
             [](const FieldSource& s, Index e) { return s.solver.elements().membrane_force(e); })},
        {"bending_moment", 3, L::Cell, three_components([](const FieldSource& s, Index e) {
             return s.solver.elements().bending_moment(e);
         })},
        {"thickness", 1, L::Cell, one_component([](const FieldSource& s, Index e) {
             return s.solver.elements().thickness(e);
         })},
        plastic_strain_field("plastic_strain_top", ShellSurface::Top),
        plastic_strain_field("plastic_strain_middle", ShellSurface::Middle),
        plastic_strain_field("plastic_strain_bottom", ShellSurface::Bottom),
    };
    if (model_can_erode(model))
        fields.push_back({"eroded", 1, L::Cell, one_component([](const FieldSource& s, Index e) {
                              return s.solver.elements().eroded(e) ? 1.0 : 0.0;
                          })});
    return fields;
}

void field_frame(const std::vector<OutputField>& fields, const FieldSource& source, Real time,
                 FieldFrame& frame) {
    frame.time = time;
    frame.points = source.positions;
    frame.triangles = source.model.triangles;
    fill_frame(fields, source, nullptr, frame);
}

void field_frame(const std::vector<OutputField>& fields, const FieldSource& source, Real time,
                 const FramePiece& piece, FieldFrame& frame) {
    frame.time = time;
    frame.points.resize(piece.particles.size());
    for (std::size_t k = 0; k < piece.particles.size(); ++k)
        frame.points[k] = source.positions[at(piece.particles[k])];
    frame.triangles = piece.triangles;
    fill_frame(fields, source, &piece, frame);
    // where each item sits in the single-process frame (exact in a double up to 2^53)
    frame.point_data.push_back({"particle_index", 1, {}});
    for (const Index p : piece.particles) frame.point_data.back().values.push_back(Real(p));
    frame.cell_data.push_back({"element_index", 1, {}});
    for (const Index e : piece.elements) frame.cell_data.back().values.push_back(Real(e));
}

FramePiece frame_piece(const Model& model, std::vector<Index> elements, bool lone_particles) {
    FramePiece piece;
    std::sort(elements.begin(), elements.end());
    piece.elements = std::move(elements);
    const std::size_t np = model.nodes.size();
    std::vector<std::uint8_t> named(np, 0), listed(np, 0);
    for (const auto& t : model.triangles)
        for (const Index p : t) named[at(p)] = 1;
    for (const Index e : piece.elements)
        for (const Index p : model.triangles[at(e)]) listed[at(p)] = 1;
    std::vector<Index> local(np, -1);
    for (std::size_t p = 0; p < np; ++p)
        if (listed[p] || (lone_particles && !named[p])) {
            local[p] = static_cast<Index>(piece.particles.size());
            piece.particles.push_back(static_cast<Index>(p));
        }
    piece.triangles.reserve(piece.elements.size());
    for (const Index e : piece.elements) {
        const auto& t = model.triangles[at(e)];
        piece.triangles.push_back({local[at(t[0])], local[at(t[1])], local[at(t[2])]});
    }
    return piece;
}

FieldFrame field_frame(const std::vector<OutputField>& fields, const FieldSource& source,
                       Real time) {
    FieldFrame frame;
    field_frame(fields, source, time, frame);
    return frame;
}

Real surface_plastic_strain(const ShellElements& elements, Index e, ShellSurface surface) {
    const int nk = elements.thickness_points(e);
    switch (surface) {
        case ShellSurface::Bottom:
            return elements.plastic_strain(e, 0);
        case ShellSurface::Top:
            return elements.plastic_strain(e, nk - 1);
        case ShellSurface::Middle:
            break;
    }
    return nk % 2 == 1 ? elements.plastic_strain(e, nk / 2)
                       : 0.5 * (elements.plastic_strain(e, 0) + elements.plastic_strain(e, nk - 1));
}

}  // namespace fpmshell
