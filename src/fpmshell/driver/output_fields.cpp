// The field list of the VTU frames and the frame built from it.
#include "fpmshell/driver/output_fields.hpp"

#include "fpmshell/core/rotation.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

namespace {

std::size_t at(Index i) { return static_cast<std::size_t>(i); }

template <class Vector3>
void put3(std::span<Real> out, const Vector3& v) {
    for (int c = 0; c < 3; ++c) out[at(c)] = v[c];
}

/// A cell field of the plastic strain at one surface.
OutputField plastic_strain_field(std::string name, ShellSurface surface) {
    return {std::move(name), 1, FieldLocation::Cell,
            [surface](const FieldSource& s, Index e, std::span<Real> out) {
                out[0] = surface_plastic_strain(s.solver.elements(), e, surface);
            }};
}

}  // namespace

std::vector<OutputField> standard_fields() {
    using L = FieldLocation;
    return {
        {"displacement", 3, L::Point,
         [](const FieldSource& s, Index p, std::span<Real> out) {
             put3(out, s.positions[at(p)] - s.solver.state().x0[at(p)]);
         }},
        {"velocity", 3, L::Point,
         [](const FieldSource& s, Index p, std::span<Real> out) {
             put3(out, s.solver.state().v[at(p)]);
         }},
        {"rotation", 3, L::Point,  // rotation vector (theory.md §1.4)
         [](const FieldSource& s, Index p, std::span<Real> out) {
             put3(out, rotation_vector(s.solver.state().rotation[at(p)]));
         }},
        {"membrane_force", 3, L::Cell,  // xx, yy, xy per unit length, element frame
         [](const FieldSource& s, Index e, std::span<Real> out) {
             put3(out, s.solver.elements().membrane_force(e));
         }},
        {"bending_moment", 3, L::Cell,
         [](const FieldSource& s, Index e, std::span<Real> out) {
             put3(out, s.solver.elements().bending_moment(e));
         }},
        {"thickness", 1, L::Cell,
         [](const FieldSource& s, Index e, std::span<Real> out) {
             out[0] = s.solver.elements().thickness(e);
         }},
        plastic_strain_field("plastic_strain_top", ShellSurface::Top),
        plastic_strain_field("plastic_strain_middle", ShellSurface::Middle),
        plastic_strain_field("plastic_strain_bottom", ShellSurface::Bottom),
    };
}

void field_frame(const std::vector<OutputField>& fields, const FieldSource& source, Real time,
                 FieldFrame& frame) {
    frame.time = time;
    frame.points = source.positions;
    frame.triangles = source.model.triangles;
    std::size_t n_point_arrays = 0, n_cell_arrays = 0;
    for (const OutputField& field : fields)
        ++(field.location == FieldLocation::Point ? n_point_arrays : n_cell_arrays);
    frame.point_data.resize(n_point_arrays);
    frame.cell_data.resize(n_cell_arrays);
    std::size_t next_point_array = 0, next_cell_array = 0;
    for (const OutputField& field : fields) {
        const bool on_points = field.location == FieldLocation::Point;
        const std::size_t n = on_points ? frame.points.size() : frame.triangles.size();
        const std::size_t width = at(field.components);
        FieldArray& array =
            on_points ? frame.point_data[next_point_array++] : frame.cell_data[next_cell_array++];
        array.name = field.name;
        array.components = field.components;
        array.values.resize(n * width);
        Real* values = array.values.data();
        // every item writes its own values: the same bytes on any number of threads
#pragma omp parallel for schedule(static) if (n >= 10000)
        for (std::size_t i = 0; i < n; ++i)
            field.value(source, static_cast<Index>(i), std::span<Real>(values + i * width, width));
    }
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
