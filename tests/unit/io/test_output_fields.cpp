// The field list of the VTU frames (driver/output_fields.hpp):
// - the standard list holds the arrays of model-format.md, by name and in file order;
// - a field added to the list is in the frame, after the standard ones, with the values its
//   entry computes, and in the .vtu text;
// - a frame of other positions (the last good state of a failed run) shows those positions and
//   the displacements from them;
// - a frame of many items (gathered in ranges, on every thread) holds each item's own values.
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fpmshell/driver/output_fields.hpp"
#include "fpmshell/io/vtu_writer.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "one_section_model.hpp"

namespace fpmshell {
namespace {

/// A free elastic plate, 4 x 4 squares unless said, with random initial velocities: every field is
/// non-zero after a few steps.
Model moving_plate(Index squares = 4) {
    PlateParams pp;
    pp.nx = pp.ny = squares;
    pp.pattern = DiagonalPattern::Alternate;
    const MeshData mesh = generate_plate(pp);
    Model m = test::one_section_model(mesh, 0.01);
    m.title = "moving plate";
    m.control.end_time = 1;
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> u(-1, 1);
    for (Index p = 0; p < m.n_particles(); ++p)
        m.initial_conditions.push_back({{p}, Vec3(u(rng), u(rng), u(rng)), Vec3::Zero()});
    return m;
}

std::vector<std::string> names(const std::vector<FieldArray>& arrays) {
    std::vector<std::string> out;
    for (const FieldArray& a : arrays) out.push_back(a.name);
    return out;
}

/// The values of the ASCII DataArray called `name` in a .vtu text.
std::vector<Real> ascii_values(const std::string& vtu, const std::string& name) {
    const std::size_t tag = vtu.find("Name=\"" + name + "\"");
    if (tag == std::string::npos) return {};
    const std::size_t begin = vtu.find('>', tag) + 1;
    std::istringstream in(vtu.substr(begin, vtu.find("</DataArray>", begin) - begin));
    std::vector<Real> values;
    for (Real v; in >> v;) values.push_back(v);
    return values;
}

TEST(OutputFields, TheStandardListHoldsTheArraysOfTheFormatInFileOrder) {
    const Model model = moving_plate();
    const ExplicitSolver solver(model);
    const FieldFrame frame =
        field_frame(standard_fields(model), {model, solver, solver.state().x}, 0);
    EXPECT_EQ(names(frame.point_data),
              (std::vector<std::string>{"displacement", "velocity", "rotation"}));
    EXPECT_EQ(names(frame.cell_data),
              (std::vector<std::string>{"membrane_force", "bending_moment", "thickness",
                                        "plastic_strain_top", "plastic_strain_middle",
                                        "plastic_strain_bottom"}));
}

TEST(OutputFields, AFieldAddedToTheListIsInTheFrameAndTheVtuWithItsValues) {
    const Model model = moving_plate();
    ExplicitSolver solver(model);
    for (int i = 0; i < 5; ++i) solver.step(1e30);
    std::vector<OutputField> fields = standard_fields(model);
    fields.push_back({"particle_mass", 1, FieldLocation::Point,
                      [](const FieldSource& s, Index first, Index last, std::span<Real> out) {
                          for (Index p = first; p < last; ++p)
                              out[static_cast<std::size_t>(p - first)] =
                                  s.solver.state().mass[static_cast<std::size_t>(p)];
                      }});
    fields.push_back({"corners", 3, FieldLocation::Cell,
                      [](const FieldSource& s, Index first, Index last, std::span<Real> out) {
                          for (Index e = first; e < last; ++e) {
                              const auto& t = s.model.triangles[static_cast<std::size_t>(e)];
                              for (std::size_t c = 0; c < 3; ++c)
                                  out[3 * static_cast<std::size_t>(e - first) + c] =
                                      static_cast<Real>(t[c]);
                          }
                      }});
    const FieldFrame frame = field_frame(fields, {model, solver, solver.state().x}, 0.25);

    ASSERT_EQ(frame.point_data.size(), 4u);
    ASSERT_EQ(frame.cell_data.size(), 7u);
    const FieldArray& mass = frame.point_data.back();
    EXPECT_EQ(mass.name, "particle_mass");
    EXPECT_EQ(mass.components, 1);
    EXPECT_EQ(mass.values, solver.state().mass);
    const FieldArray& corners = frame.cell_data.back();
    EXPECT_EQ(corners.name, "corners");
    ASSERT_EQ(corners.values.size(), 3 * model.triangles.size());
    for (std::size_t e = 0; e < model.triangles.size(); ++e)
        for (std::size_t c = 0; c < 3; ++c)
            EXPECT_EQ(corners.values[3 * e + c], static_cast<Real>(model.triangles[e][c]));
    // The standard fields around the new ones are those of the solver state.
    const FieldArray& velocity = frame.point_data[1];
    for (std::size_t p = 0; p < solver.state().v.size(); ++p)
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(velocity.values[3 * p + static_cast<std::size_t>(c)], solver.state().v[p][c]);

    // In the .vtu text, read back exactly (ASCII values are written in the shortest form that
    // reads back to the same double).
    const std::string vtu = vtu_text(frame, VtuEncoding::Ascii);
    EXPECT_NE(
        vtu.find("<DataArray type=\"Float64\" Name=\"particle_mass\" NumberOfComponents=\"1\""),
        std::string::npos);
    EXPECT_EQ(ascii_values(vtu, "particle_mass"), solver.state().mass);
    EXPECT_EQ(ascii_values(vtu, "corners"), corners.values);
    EXPECT_LT(vtu.find("Name=\"particle_mass\""), vtu.find("<CellData>"));
    EXPECT_GT(vtu.find("Name=\"corners\""), vtu.find("<CellData>"));
}

TEST(OutputFields, AFrameOfOtherPositionsShowsThemAndTheirDisplacements) {
    const Model model = moving_plate();
    ExplicitSolver solver(model);
    solver.step(1e30);
    std::vector<Vec3> positions = solver.state().x;
    for (Vec3& x : positions) x += Vec3(0.5, -0.25, 2.0);
    const FieldFrame frame = field_frame(standard_fields(model), {model, solver, positions}, 0);
    EXPECT_EQ(frame.points, positions);
    const FieldArray& displacement = frame.point_data[0];
    for (std::size_t p = 0; p < positions.size(); ++p) {
        const Vec3 u = positions[p] - solver.state().x0[p];
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(displacement.values[3 * p + static_cast<std::size_t>(c)], u[c]);
    }
}

TEST(OutputFields, EveryItemOfALargeFrameHoldsItsOwnValues) {
    // 60 x 60 squares: 7 200 triangles and 3 721 particles, more than one range of items
    const Model model = moving_plate(60);
    ExplicitSolver solver(model);
    for (int i = 0; i < 3; ++i) solver.step(1e30);
    const FieldFrame frame =
        field_frame(standard_fields(model), {model, solver, solver.state().x}, 0);
    const FieldArray& velocity = frame.point_data[1];
    ASSERT_EQ(velocity.values.size(), 3 * solver.state().v.size());
    for (std::size_t p = 0; p < solver.state().v.size(); ++p)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(velocity.values[3 * p + static_cast<std::size_t>(c)], solver.state().v[p][c])
                << "particle " << p;
    const FieldArray& membrane = frame.cell_data[0];
    const FieldArray& thickness = frame.cell_data[2];
    ASSERT_EQ(membrane.values.size(), 3 * model.triangles.size());
    for (Index e = 0; e < model.n_elements(); ++e) {
        const auto ue = static_cast<std::size_t>(e);
        const Voigt3 n = solver.elements().membrane_force(e);
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(membrane.values[3 * ue + static_cast<std::size_t>(c)], n[c])
                << "element " << e;
        ASSERT_EQ(thickness.values[ue], solver.elements().thickness(e));
    }
}

}  // namespace
}  // namespace fpmshell
