// Unit tests of the Gmsh .msh reader (mesh/gmsh_reader.hpp) on small files written here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/mesh/gmsh_reader.hpp"

namespace fpmshell {
namespace {

/// A fresh folder for the running test, removed at the end of the test.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = std::filesystem::temp_directory_path() /
                ("fpmshell_gmsh_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    [[nodiscard]] std::filesystem::path operator/(const std::string& name) const {
        return path_ / name;
    }

private:
    std::filesystem::path path_;
};

std::string write(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path) << text;
    return path.string();
}

// A 2 x 1 plate in format 4.1: one quadrangle (tags 11 12 15 14) and two triangles on surface
// 1, a line on curve 1 (physical "left"), a point element on point 1 (unnamed physical 5), and
// an orphan node 99 used by no element. Node tags start at 11 to test the renumbering.
const char* const k_msh41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
2
1 1 "left"
2 2 "skin"
$EndPhysicalNames
$Entities
1 1 1 0
1 2 0 0 1 5
1 0 0 0 0 1 0 1 1 0
1 0 0 0 2 1 0 1 2 0
$EndEntities
$Nodes
3 7 11 99
0 1 0 1
13
2 0 0
1 1 0 2
11
14
0 0 0
0 1 0
2 1 0 4
12
15
16
99
1 0 0
1 1 0
2 1 0
5 5 5
$EndNodes
$Elements
4 5 1 5
0 1 15 1
1 13
1 1 1 1
2 11 14
2 1 3 1
3 11 12 15 14
2 1 2 2
4 12 13 16
5 12 16 15
$EndElements
)";

// Reads format 4.1: the quadrangle becomes two triangles with its orientation, nodes are
// renumbered compactly in tag order without the orphan, the surface group gives an element set
// and a node set, the line group and the unnamed point group give node sets.
TEST(GmshReader, ReadsTrianglesSplitsQuadsAndMapsPhysicalGroups) {
    const TempDir dir;
    const MeshData m = read_gmsh(write(dir / "plate.msh", k_msh41));
    ASSERT_EQ(m.nodes.size(), 6U);
    EXPECT_EQ(m.nodes[0], Vec3(0, 0, 0));  // tag 11
    EXPECT_EQ(m.nodes[2], Vec3(2, 0, 0));  // tag 13
    EXPECT_EQ(m.nodes[5], Vec3(2, 1, 0));  // tag 16
    ASSERT_EQ(m.triangles.size(), 4U);
    ASSERT_EQ(m.element_tag.size(), 4U);
    Real area = 0;
    int from_quad = 0;
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
        const auto& t = m.triangles[e];
        const Vec3 n =
            (m.nodes[static_cast<std::size_t>(t[1])] - m.nodes[static_cast<std::size_t>(t[0])])
                .cross(m.nodes[static_cast<std::size_t>(t[2])] -
                       m.nodes[static_cast<std::size_t>(t[0])]);
        EXPECT_GT(n.z(), 0.0) << "triangle " << e;
        area += 0.5 * n.norm();
        if (m.element_tag[e] == 3) {
            ++from_quad;
            // Equal diagonals: split along the first one, (a, b, c) and (a, c, d).
            EXPECT_TRUE(t == (std::array<Index, 3>{0, 1, 4}) ||
                        t == (std::array<Index, 3>{0, 4, 3}));
        }
    }
    EXPECT_EQ(from_quad, 2);
    EXPECT_DOUBLE_EQ(area, 2.0);
    EXPECT_EQ(m.element_sets.at("skin"), (std::vector<Index>{0, 1, 2, 3}));
    EXPECT_EQ(m.element_sets.size(), 1U);
    EXPECT_EQ(m.node_sets.at("skin"), (std::vector<Index>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(m.node_sets.at("left"), (std::vector<Index>{0, 3}));
    EXPECT_EQ(m.node_sets.at("physical_5"), (std::vector<Index>{2}));
    EXPECT_EQ(m.node_sets.size(), 3U);
}

// Reads the legacy format 2.2 too, and a quadrangle with unequal diagonals is split along the
// shorter one (nodes 2-4 here).
TEST(GmshReader, ReadsFormat22AndSplitsAlongTheShorterDiagonal) {
    const TempDir dir;
    const std::string path = write(dir / "quad.msh", R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
4
1 0 0 0
2 3 0 0
3 3.5 1 0
4 0.2 1 0
$EndNodes
$Elements
1
1 3 2 7 1 1 2 3 4
$EndElements
)");
    const MeshData m = read_gmsh(path);
    ASSERT_EQ(m.triangles.size(), 2U);
    EXPECT_EQ(m.triangles[0], (std::array<Index, 3>{0, 1, 3}));
    EXPECT_EQ(m.triangles[1], (std::array<Index, 3>{1, 2, 3}));
    EXPECT_EQ(m.node_sets.at("physical_7").size(), 4U);
    EXPECT_EQ(m.element_sets.at("physical_7").size(), 2U);
}

// Missing files, files that are not meshes, and meshes without surface elements are refused
// with an InputError naming the file (and Gmsh is left finalised: the next read works).
TEST(GmshReader, RefusesWhatIsNotASurfaceMesh) {
    const TempDir dir;
    auto expect_error = [](const std::string& path, const std::string& part) {
        try {
            (void)read_gmsh(path);
            ADD_FAILURE() << "no error for " << path;
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(path), std::string::npos) << what;
            EXPECT_NE(what.find(part), std::string::npos) << what;
        }
    };
    expect_error((dir / "missing.msh").string(), "cannot open");
    expect_error(write(dir / "text.msh", "Point(1) = {0, 0, 0};\n"), "not a Gmsh mesh file");
    expect_error(write(dir / "empty.msh", ""), "not a Gmsh mesh file");
    expect_error(write(dir / "truncated.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2"),
                 "cannot read");
    expect_error(
        write(dir / "garbage.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Elements\nxx\n"), "");
    expect_error(write(dir / "lines.msh", R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
2
1 0 0 0
2 1 0 0
$EndNodes
$Elements
1
1 1 2 1 1 1 2
$EndElements
)"),
                 "no triangle");
    expect_error(write(dir / "quadratic.msh", R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
6
1 0 0 0
2 1 0 0
3 0 1 0
4 0.5 0 0
5 0.5 0.5 0
6 0 0.5 0
$EndNodes
$Elements
1
1 9 2 1 1 1 2 3 4 5 6
$EndElements
)"),
                 "not supported");
    EXPECT_EQ(read_gmsh(write(dir / "again.msh", k_msh41)).triangles.size(), 4U);
}

// A file that makes Gmsh 4.8 itself crash (a physical name of dimension 23: segmentation fault
// inside GModel::setPhysicalName, found by fuzzing) gives an InputError naming the file, and
// the program goes on: the read runs in a child process. The write out of bounds is undefined
// behaviour: depending on the heap the child may also hang instead (seen when every unit test
// runs in one process), so the test gives it 20 s, not the default 10 minutes; both ways end
// in the same InputError.
TEST(GmshReader, SurvivesAGmshCrash) {
    const TempDir dir;
    std::string text = k_msh41;
    text.replace(text.find("2 2 \"skin\""), 1, "23");
    const std::string path = write(dir / "crash.msh", text);
    try {
        (void)read_gmsh(path, std::chrono::seconds(20));
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0U) << e.what();
    }
    EXPECT_EQ(read_gmsh(write(dir / "good.msh", k_msh41)).triangles.size(), 4U);
}

}  // namespace
}  // namespace fpmshell
