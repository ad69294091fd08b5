// The materials seam (src/fpmshell/materials/material_law.hpp): a law that lives only in the
// tests (tests/material_law/damaging_elastic/, one folder and its registry line) is named by a
// model file, computes its own point state in the solver, and resumes from a restart file bit
// for bit; tests/mpi/distributed_test.py runs its model on 2 ranks against one process.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../../material_law/damaging_elastic/damaging_elastic.hpp"
#include "../one_section_model.hpp"
#include "fpmshell/core/errors.hpp"
#include "fpmshell/driver/run_driver.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/materials/material_law.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {
namespace {

namespace fs = std::filesystem;

const std::string k_model =
    std::string(FPMSHELL_SOURCE_DIR) + "/tests/material_law/damaging_elastic/model.yaml";

fs::path fresh_dir(const std::string& name) {
    const fs::path d = fs::temp_directory_path() /
                       ("fpmshell_law_seam_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    return d;
}

std::string bytes_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(MaterialLawSeam, TheTestLawIsRegisteredBesideTheLibrarysOwn) {
    ASSERT_NE(find_material_law("damaging_elastic_test"), nullptr);
    for (const char* law :
         {"elastic", "j2_plastic", "johnson_cook", "tabulated", "power_law", "rigid"})
        EXPECT_NE(find_material_law(law), nullptr) << law;
}

TEST(MaterialLawSeam, AModelFileNamesItAndItsKeysAreChecked) {
    const Model m = read_model(k_model);
    ASSERT_EQ(m.materials[0].law, "damaging_elastic_test");
    const auto& p =
        std::any_cast<const test::DamagingElasticParameters&>(m.materials[0].parameters);
    EXPECT_EQ(p.damage_strain, 0.01);
    EXPECT_EQ(p.residual_fraction, 0.2);
    // its keys are its own: refused on another law, and checked on its own
    const auto message = [](const std::string& text) {
        const fs::path d = fresh_dir("keys");
        fs::create_directories(d);
        std::ofstream(d / "model.yaml") << text;
        try {
            (void)read_model((d / "model.yaml").string());
        } catch (const InputError& e) {
            fs::remove_all(d);
            return std::string(e.what());
        }
        fs::remove_all(d);
        return std::string("no error");
    };
    std::ifstream in(k_model);
    std::stringstream text;
    text << in.rdbuf();
    const std::string model = text.str();
    const auto replaced = [&](const std::string& from, const std::string& to) {
        std::string s = model;
        s.replace(s.find(from), from.size(), to);
        return s;
    };
    EXPECT_NE(message(replaced("damaging_elastic_test", "elastic"))
                  .find("key 'materials.soft.damage_strain': belongs to materials (type: "
                        "damaging_elastic_test), not to type elastic"),
              std::string::npos);
    EXPECT_NE(message(replaced("residual_fraction: 0.2", "residual_fraction: 1.5"))
                  .find(":8: key 'materials.soft.residual_fraction': must be in (0, 1]"),
              std::string::npos)
        << message(replaced("residual_fraction: 0.2", "residual_fraction: 1.5"));
}

TEST(MaterialLawSeam, ItsPointsFollowTheLawInAHomogeneousStretch) {
    // the model file's strip stretched equibiaxially, every particle at its own velocity
    // 100 (x0, y0, 0): lambda = 1 + 100 t to 1.2, the solver's strain ln(lambda) each way
    Model m = read_model(k_model);
    m.boundary.clear();
    m.initial_conditions.clear();
    m.control.end_time = 2e-3;
    test::prescribe_velocity_field(
        m, [](const Vec3& x0) { return Vec3(1e2 * x0.x(), 1e2 * x0.y(), 0); },
        {false, false, false, true, true, true});
    ExplicitSolver s(m);
    while (s.time() < m.control.end_time) s.step(m.control.end_time - s.time());
    const Real eps = std::log(1.2), kappa = std::sqrt(2.0) * eps;
    const Real d = 0.8 * (1.0 - 0.01 / kappa);
    const Real sigma = (1.0 - d) * 2.1e11 * eps / (1.0 - 0.3);  // plane stress, equibiaxial
    for (Index e = 0; e < m.n_elements(); e += 13)
        for (std::size_t p = 0; p < 2; ++p) {
            const MaterialPoint mp = s.elements().point_state(e, p);
            // the strain lags the motion by less than a step's increment, 100 dt = 6e-5 of
            // eps = 0.18 (3e-4 of it); the stress moves by less than the strain (dsigma/sigma =
            // 0.87 deps/eps here)
            EXPECT_NEAR(mp.stress(0), sigma, 5e-4 * sigma) << e;
            EXPECT_NEAR(mp.stress(1), sigma, 5e-4 * sigma) << e;
            EXPECT_NEAR(mp.stress(2), 0.0, 1e-9 * sigma) << e;
            EXPECT_EQ(mp.plastic_strain, 0.0);
        }
}

TEST(MaterialLawSeam, ItsStateResumesFromARestartBitForBit) {
    const Model model = read_model(k_model);
    RunOptions straight;
    straight.output_dir = fresh_dir("straight");
    straight.echo = false;
    straight.quiet = true;
    ASSERT_EQ(run_model(model, straight), 0);
    RunOptions first = straight;
    first.output_dir = fresh_dir("pieces");
    first.stop_at_step = 300;
    ASSERT_EQ(run_model(model, first), 0);
    RunOptions second = first;
    second.stop_at_step = 0;
    second.resume = true;
    ASSERT_EQ(run_model(model, second), 0);
    for (const char* file : {"history.csv", "energy.csv"})
        EXPECT_EQ(bytes_of(first.output_dir / file), bytes_of(straight.output_dir / file)) << file;
    for (const auto& entry : fs::directory_iterator(straight.output_dir / "fields"))
        EXPECT_EQ(bytes_of(first.output_dir / "fields" / entry.path().filename()),
                  bytes_of(entry.path()))
            << entry.path().filename();
    fs::remove_all(straight.output_dir);
    fs::remove_all(first.output_dir);
}

TEST(MaterialLawSeam, ItsKappaIsStateThatARestartMustCarry) {
    // the strip pulled and let go: past the peak the stress follows the damaged stiffness, so a
    // run that lost kappa at the restart would answer with the undamaged one
    const test::DamagingElastic law(2.1e11, 0.3, {0.01, 0.2});
    test::DamagingElastic::Point p;
    law.update(p, Voigt3(0.03, 0, 0), 0, p);
    test::DamagingElastic::Point unloaded = p, forgotten;
    law.update(unloaded, Voigt3(-0.02, 0, 0), 0, unloaded);
    forgotten.strain = unloaded.strain;  // kappa lost
    law.update(forgotten, Voigt3::Zero(), 0, forgotten);
    EXPECT_LT(unloaded.stress(0), 0.6 * forgotten.stress(0));
    EXPECT_EQ(unloaded.kappa, p.kappa);
}

}  // namespace
}  // namespace fpmshell
