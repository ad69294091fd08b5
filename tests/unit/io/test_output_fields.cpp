// The field list of the VTU frames (driver/output_fields.hpp):
// - the standard list holds the arrays of model-format.md, by name and in file order;
// - a field added to the list is in the frame, after the standard ones, with the values its
//   entry computes, and in the .vtu text;
// - a frame of other positions (the last good state of a failed run) shows those positions and
//   the displacements from them;
// - a frame of many items (gathered in ranges, on every thread) holds each item's own values;
// - summary.json's plastic strain peaks (per surface the peak and the lowest element reaching
//   it; the largest, the first surface of bottom, middle, top that reaches it) are those of a
//   loop over every element in order, as one process takes them; none on an elastic plate;
// - the pieces of a frame (a distributed run's, one per rank) hold every element once, the
//   particles of their elements (and, asked, those of no element) and each item's values of the
//   whole frame, with the item's index in it.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fpmshell/driver/output_fields.hpp"
#include "fpmshell/driver/plastic_strain_peaks.hpp"
#include "fpmshell/io/model_reader.hpp"
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
                      [](const FieldSource& s, std::span<const Index> items, std::span<Real> out) {
                          for (std::size_t k = 0; k < items.size(); ++k)
                              out[k] = s.solver.state().mass[static_cast<std::size_t>(items[k])];
                      }});
    fields.push_back({"corners", 3, FieldLocation::Cell,
                      [](const FieldSource& s, std::span<const Index> items, std::span<Real> out) {
                          for (std::size_t k = 0; k < items.size(); ++k) {
                              const auto& t = s.model.triangles[static_cast<std::size_t>(items[k])];
                              for (std::size_t c = 0; c < 3; ++c)
                                  out[3 * k + c] = static_cast<Real>(t[c]);
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

TEST(OutputFields, PiecesOfAFrameJoinIntoTheWholeFrame) {
    // 40 x 40 squares: 3 200 triangles, a piece of more than one range of items
    const Model model = moving_plate(40);
    ExplicitSolver solver(model);
    for (int i = 0; i < 3; ++i) solver.step(1e30);
    const std::vector<OutputField> fields = standard_fields(model);
    const FieldSource source{model, solver, solver.state().x};
    const FieldFrame whole = field_frame(fields, source, 0.5);
    // the elements dealt to three pieces out of order (a rank's units are not ascending)
    std::vector<std::vector<Index>> dealt(3);
    for (Index e = model.n_elements() - 1; e >= 0; --e)
        dealt[static_cast<std::size_t>((e * 7) % 3)].push_back(e);
    std::vector<int> cells_seen(model.triangles.size(), 0), points_seen(model.nodes.size(), 0);
    for (std::size_t r = 0; r < dealt.size(); ++r) {
        const FramePiece piece = frame_piece(model, dealt[r], r == 0);
        ASSERT_TRUE(std::is_sorted(piece.elements.begin(), piece.elements.end()));
        FieldFrame part;
        field_frame(fields, source, 0.5, piece, part);
        EXPECT_EQ(part.time, 0.5);
        ASSERT_EQ(part.point_data.size(), whole.point_data.size() + 1);
        ASSERT_EQ(part.cell_data.size(), whole.cell_data.size() + 1);
        EXPECT_EQ(part.point_data.back().name, "particle_index");
        EXPECT_EQ(part.cell_data.back().name, "element_index");
        for (std::size_t k = 0; k < piece.particles.size(); ++k) {
            const auto p = static_cast<std::size_t>(piece.particles[k]);
            ++points_seen[p];
            EXPECT_EQ(part.points[k], whole.points[p]);
            EXPECT_EQ(part.point_data.back().values[k], Real(piece.particles[k]));
            for (std::size_t a = 0; a < whole.point_data.size(); ++a)
                for (std::size_t c = 0; c < 3; ++c)
                    ASSERT_EQ(part.point_data[a].values[3 * k + c],
                              whole.point_data[a].values[3 * p + c]);
        }
        for (std::size_t k = 0; k < piece.elements.size(); ++k) {
            const auto e = static_cast<std::size_t>(piece.elements[k]);
            ++cells_seen[e];
            for (std::size_t c = 0; c < 3; ++c)
                EXPECT_EQ(piece.particles[static_cast<std::size_t>(part.triangles[k][c])],
                          model.triangles[e][c]);
            EXPECT_EQ(part.cell_data.back().values[k], Real(piece.elements[k]));
            for (std::size_t a = 0; a < whole.cell_data.size(); ++a) {
                const auto n = static_cast<std::size_t>(whole.cell_data[a].components);
                for (std::size_t c = 0; c < n; ++c)
                    ASSERT_EQ(part.cell_data[a].values[n * k + c],
                              whole.cell_data[a].values[n * e + c]);
            }
        }
    }
    EXPECT_TRUE(std::all_of(cells_seen.begin(), cells_seen.end(), [](int n) { return n == 1; }));
    EXPECT_TRUE(std::all_of(points_seen.begin(), points_seen.end(), [](int n) { return n >= 1; }));
    // a particle that no triangle names: in the piece that asks for such particles only
    Model with_lone = model;
    with_lone.nodes.push_back(Vec3(5, 5, 0));
    const auto lone = static_cast<Index>(with_lone.nodes.size() - 1);
    EXPECT_EQ(frame_piece(with_lone, dealt[0], true).particles.back(), lone);
    EXPECT_NE(frame_piece(with_lone, dealt[0], false).particles.back(), lone);
    EXPECT_EQ(frame_piece(with_lone, dealt[1], false).particles,
              frame_piece(model, dealt[1], false).particles);
}

TEST(PlasticStrainPeaks, AreThoseOfALoopOverEveryElementInOrder) {
    Model model = read_model(std::string(FPMSHELL_SOURCE_DIR) +
                             "/validation/spherical_cap_plastic/model.yaml");
    ExplicitSolver solver(model);
    for (int i = 0; i < 400; ++i) solver.step(1e30);
    const PlasticStrainPeaks peaks = plastic_strain_peaks(solver);
    const ShellSurface surfaces[] = {ShellSurface::Bottom, ShellSurface::Middle, ShellSurface::Top};
    Real best = 0;
    int best_surface = -1;
    Index best_element = -1;
    int yielded = 0;
    for (std::size_t s = 0; s < 3; ++s) {
        Real peak = 0;
        Index at = -1;
        for (Index e = 0; e < model.n_elements(); ++e) {
            const Real v = surface_plastic_strain(solver.elements(), e, surfaces[s]);
            yielded += v > 0 ? 1 : 0;
            if (v > peak) {
                peak = v;
                at = e;
            }
            if (v > best) {
                best = v;
                best_surface = static_cast<int>(s);
                best_element = e;
            }
        }
        EXPECT_EQ(peaks.peak[s], peak) << s;
        EXPECT_EQ(peaks.element[s], at) << s;
    }
    ASSERT_GT(yielded, 0) << "the cap has not yielded: the test compares nothing";
    EXPECT_EQ(peaks.surface(), best_surface);
    EXPECT_EQ(peaks.element[static_cast<std::size_t>(best_surface)], best_element);

    // equal peaks: the first surface that reaches the largest
    PlasticStrainPeaks tied;
    tied.peak = {0.1, 0.2, 0.2};
    EXPECT_EQ(tied.surface(), 1);
    // none yielded: no surface, no element
    const Model elastic = moving_plate();
    ExplicitSolver still(elastic);
    const PlasticStrainPeaks none = plastic_strain_peaks(still);
    EXPECT_EQ(none.surface(), -1);
    EXPECT_EQ(none.element, (std::array<Index, 3>{-1, -1, -1}));
}

}  // namespace
}  // namespace fpmshell
