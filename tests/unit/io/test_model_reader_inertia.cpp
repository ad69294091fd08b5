// The `inertia` key of a section of a rigid material (model-format.md, theory.md eqs. 6.11-8,
// 6.11-9) read from YAML over an LS-DYNA mesh file whose *ELEMENT_SOLID gives a part's outer
// faces: `enclosed` gives the cube's mass, centre and tensor; given numbers are read as written;
// a wrong use is one InputError naming file, line and key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/model_reader.hpp"

namespace fpmshell {
namespace {

/// A 1 x 1 shell square (part 1, two triangles' worth: one quadrangle) at z = 0 and a rigid
/// unit cube of one hexahedron (part 2) from z = 1 to 2, written with the model into a folder.
class CubeModel {
public:
    CubeModel() {
        dir_ = std::filesystem::temp_directory_path() /
               ("fpmshell_inertia_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir_);
        std::ofstream(dir_ / "mesh.k")
            << "*KEYWORD\n*NODE\n"
               "       1               0               0               0\n"
               "       2               1               0               0\n"
               "       3               1               1               0\n"
               "       4               0               1               0\n"
               "      11               0               0               1\n"
               "      12               1               0               1\n"
               "      13               1               1               1\n"
               "      14               0               1               1\n"
               "      15               0               0               2\n"
               "      16               1               0               2\n"
               "      17               1               1               2\n"
               "      18               0               1               2\n"
               "*ELEMENT_SHELL\n"
               "       1       1       1       2       3       4\n"
               "*ELEMENT_SOLID\n"
               "      11       2      11      12      13      14"
               "      15      16      17      18\n*END\n";
    }
    ~CubeModel() {
        std::error_code ec;
        std::filesystem::remove_all(dir_, ec);
    }
    CubeModel(const CubeModel&) = delete;
    CubeModel& operator=(const CubeModel&) = delete;

    /// Reads the model whose part 2 section is `block` (a YAML flow map); `block_material`:
    /// the type of the material of part 2.
    Model read(const std::string& block, const std::string& block_material = "rigid") const {
        const std::string text =
            "title: cube\n"
            "mesh: {file: mesh.k}\n"
            "materials:\n"
            "  steel: {type: elastic, density: 8000, youngs_modulus: 2.0e11, poisson_ratio: 0.3}\n"
            "  block: {type: " +
            block_material +
            ", density: 8000, youngs_modulus: 2.0e11, poisson_ratio: 0.3}\n"
            "sections:\n"
            "  - {elements: part_1, material: steel, thickness: 0.01}\n"
            "  - " +
            block +
            "\n"
            "control: {end_time: 1.0e-3}\n";
        std::ofstream(dir_ / "model.yaml") << text;
        return read_model((dir_ / "model.yaml").string());
    }

private:
    std::filesystem::path dir_;
};

/// The InputError of reading `block`, or "" when it reads.
std::string error_of(const CubeModel& cube, const std::string& block,
                     const std::string& material = "rigid") {
    try {
        (void)cube.read(block, material);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(ModelReaderInertia, EnclosedGivesTheCubesMassCentreAndTensor) {
    const CubeModel cube;
    const Model m =
        cube.read("{elements: part_2, material: block, thickness: 0, inertia: enclosed}");
    ASSERT_EQ(m.sections.size(), 2u);
    const Section& s = m.sections[1];
    ASSERT_TRUE(s.has_inertia);
    EXPECT_NEAR(s.inertia.mass, 8000, 1e-9);  // flat faces: rounding only
    EXPECT_LT((s.inertia.centre - Vec3(0.5, 0.5, 1.5)).norm(), 1e-12);
    EXPECT_LT((s.inertia.tensor - (8000.0 / 6.0) * Mat3::Identity()).norm(), 1e-9);
    EXPECT_EQ(m.triangles.size(), 2u + 12u);  // the square and the cube's six split faces
}

TEST(ModelReaderInertia, GivenNumbersAreReadAsWritten) {
    const CubeModel cube;
    const Model m = cube.read(
        "{elements: part_2, material: block, thickness: 0, inertia: {mass: 9000, centre: [0.5, "
        "0.55, 1.5], tensor: [1500, 10, -20, 1400, 30, 1600]}}");
    const Section& s = m.sections[1];
    EXPECT_EQ(s.inertia.mass, 9000);
    EXPECT_EQ(s.inertia.centre, Vec3(0.5, 0.55, 1.5));
    EXPECT_EQ(s.inertia.tensor(0, 1), 10);
    EXPECT_EQ(s.inertia.tensor(2, 0), -20);
    EXPECT_EQ(s.inertia.tensor(2, 1), 30);
    EXPECT_EQ(s.inertia.tensor(1, 1), 1400);
}

TEST(ModelReaderInertia, AWrongUseIsOneSentenceNamingTheKey) {
    const CubeModel cube;
    const auto has = [](const std::string& message, const std::string& part) {
        return message.find(part) != std::string::npos;
    };
    std::string e = error_of(cube,
                             "{elements: part_2, material: block, thickness: 0, "
                             "inertia: enclosed}",
                             "elastic");
    EXPECT_TRUE(has(e, "sections.1.inertia") && has(e, "rigid material")) << e;
    e = error_of(cube, "{elements: part_2, material: block, thickness: 0}");
    EXPECT_TRUE(has(e, "sections.1.thickness") && has(e, "greater than 0")) << e;
    e = error_of(cube, "{elements: all, material: block, thickness: 0, inertia: enclosed}");
    EXPECT_TRUE(has(e, "sections.1.inertia") && has(e, "close a solid")) << e;
    e = error_of(cube,
                 "{elements: part_2, material: block, thickness: 0, inertia: {mass: 1, centre: "
                 "[0.5, 0.5, 1.5], tensor: [1, 0, 0, 1, 0, 3]}}");
    EXPECT_TRUE(has(e, "sections.1.inertia.tensor") && has(e, "principal moments")) << e;
    e = error_of(cube,
                 "{elements: part_2, material: block, thickness: 0, inertia: {mass: 1, centre: "
                 "[5, 0.5, 1.5], tensor: [1, 0, 0, 1, 0, 1]}}");
    EXPECT_TRUE(has(e, "sections.1.inertia") && has(e, "negative share")) << e;
    e = error_of(cube, "{elements: part_2, material: block, thickness: 0, inertia: solid}");
    EXPECT_TRUE(has(e, "sections.1.inertia") && has(e, "enclosed")) << e;
}

}  // namespace fpmshell
