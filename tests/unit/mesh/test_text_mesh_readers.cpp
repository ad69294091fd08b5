// Unit tests of the Abaqus .inp and LS-DYNA .k shell-mesh readers (mesh/abaqus_reader.hpp,
// mesh/lsdyna_reader.hpp) on small files written here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/mesh/abaqus_reader.hpp"
#include "fpmshell/mesh/lsdyna_reader.hpp"

namespace fpmshell {
namespace {

/// A fresh folder for the running test, removed at the end of the test.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ =
            std::filesystem::temp_directory_path() /
            ("fpmshell_text_mesh_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    [[nodiscard]] const std::filesystem::path& folder() const { return path_; }
    [[nodiscard]] std::string write(const std::string& name, const std::string& text) const {
        const auto p = path_ / name;
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }

private:
    std::filesystem::path path_;
};

Real area_and_check_normals(const MeshData& m) {
    Real area = 0;
    for (const auto& t : m.triangles) {
        const Vec3 n =
            (m.nodes[static_cast<std::size_t>(t[1])] - m.nodes[static_cast<std::size_t>(t[0])])
                .cross(m.nodes[static_cast<std::size_t>(t[2])] -
                       m.nodes[static_cast<std::size_t>(t[0])]);
        EXPECT_GT(n.z(), 0.0);
        area += 0.5 * n.norm();
    }
    return area;
}

template <typename Read>
void expect_error(Read read, const std::string& path, const std::string& where,
                  const std::string& part) {
    try {
        (void)read(path);
        ADD_FAILURE() << "no error for " << path;
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path + where, 0), 0U) << what;
        EXPECT_NE(what.find(part), std::string::npos) << what << "\n  expected: " << part;
    }
}

// Abaqus: nodes (with NSET=), S4R and S3 elements (with ELSET= and a continued card), line
// elements whose ELSET becomes a node set, *NSET/*ELSET lists, GENERATE and set names in set
// data; unused nodes dropped, quads split, other keywords skipped.
TEST(AbaqusReader, ReadsShellsAndSets) {
    const TempDir dir;
    const std::string path = dir.write("plate.inp", R"(*Heading
 test plate
** a comment
*Node, nset=AllNodes
  1, 0., 0., 0.
  2, 1., 0., 0.
  3, 2., 0.
  4, 0., 1., 0.
  5, 1., 1., 0.
  6, 2., 1., 0.
  7, 9., 9., 9.
*Element, type=S4R, elset=Skin
 1, 1, 2, 5, 4
*ELEMENT, TYPE=S3, ELSET=skin
 2, 2, 3, 6
 3, 2, 6,
 5
*Element, type=T3D2, elset=LeftEdge
 10, 1, 4
*Nset, nset=Corner
 3,
*Nset, nset=Bottom, generate
 1, 3, 1
*Elset, elset=Tris
 2, 3
*Elset, elset=Both
 Tris, 1
*Material, name=Steel
*Elastic
 210000., 0.3
)");
    const MeshData m = read_abaqus(path);
    ASSERT_EQ(m.nodes.size(), 6U);
    ASSERT_EQ(m.triangles.size(), 4U);
    EXPECT_DOUBLE_EQ(area_and_check_normals(m), 2.0);
    EXPECT_EQ(m.element_tag, (std::vector<std::int64_t>{1, 1, 2, 3}));
    using V = std::vector<Index>;
    EXPECT_EQ(m.node_sets.at("AllNodes"), (V{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(m.node_sets.at("Corner"), (V{2}));
    EXPECT_EQ(m.node_sets.at("Bottom"), (V{0, 1, 2}));
    EXPECT_EQ(m.node_sets.at("LeftEdge"), (V{0, 3}));
    EXPECT_EQ(m.node_sets.at("Tris"), (V{1, 2, 4, 5}));
    EXPECT_EQ(m.element_sets.at("Skin"), (V{0, 1, 2, 3}));  // "skin" is the same set
    EXPECT_EQ(m.element_sets.at("Tris"), (V{2, 3}));
    EXPECT_EQ(m.element_sets.at("Both"), (V{0, 1, 2, 3}));
    EXPECT_EQ(m.element_sets.count("LeftEdge"), 0U);
}

// Abaqus errors name the file and the line: unsupported element types, undefined nodes,
// *INCLUDE, bad numbers, unknown set names, files without shells.
TEST(AbaqusReader, ReportsErrorsWithLines) {
    const TempDir dir;
    const std::string nodes = "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n";
    expect_error(read_abaqus, dir.write("a.inp", nodes + "*ELEMENT, TYPE=C3D8\n1, 1, 2, 3\n"),
                 ":5: ", "element type C3D8 is not supported");
    expect_error(read_abaqus, dir.write("b.inp", nodes + "*ELEMENT, TYPE=S3\n1, 1, 2, 9\n"),
                 ":6: ", "refers to node 9");
    expect_error(read_abaqus, dir.write("c.inp", "*INCLUDE, INPUT=mesh.inp\n"),
                 ":1: ", "*INCLUDE is not supported");
    expect_error(read_abaqus, dir.write("d.inp", "*NODE\n1, 0, abc, 0\n"),
                 ":2: ", "'abc' is not a finite number");
    expect_error(read_abaqus, dir.write("e.inp", nodes + "*NSET, NSET=A\nB\n"),
                 ":6: ", "neither a number nor the name of a set");
    expect_error(read_abaqus, dir.write("f.inp", nodes), ": ", "no shell element");
    expect_error(read_abaqus, dir.write("g.inp", nodes + "*ELEMENT, TYPE=S3\n1, 1, 2\n"),
                 ":6: ", "needs its number and 3 node numbers");
    expect_error(read_abaqus, dir.write("h.inp", nodes + "*NODE\n2, 5, 5, 5\n"),
                 ":6: ", "node 2 is defined twice");
    expect_error(read_abaqus,
                 (std::filesystem::temp_directory_path() / "fpmshell_no_such_mesh.inp").string(),
                 ": ", "cannot open");
}

// LS-DYNA: fixed-width, comma-separated and blank-separated cards, triangles as n3 = n4,
// *ELEMENT_SHELL_THICKNESS extra cards skipped, *SET_NODE_LIST_TITLE, *SET_SHELL_LIST,
// *SET_NODE_LIST_GENERATE and the part sets.
TEST(LsDynaReader, ReadsShellsAndSets) {
    const TempDir dir;
    const std::string path = dir.write("plate.k", R"(*KEYWORD
$ comment
*NODE
       1             0.0             0.0             0.0
       2             1.0             0.0             0.0
       3             2.0             0.0             0.0
       4             0.0             1.0             0.0
       5             1.0             1.0             0.0
6 2.0 1.0 0.0
*ELEMENT_SHELL
       1       1       1       2       5       4
       2       2       2       3       6       6
*ELEMENT_SHELL_THICKNESS
3,2,2,6,5,5
0.1,0.1,0.1,0.1
*SET_NODE_LIST_TITLE
clamp
         1       0.0       0.0       0.0       0.0
         1         4
*SET_SHELL_LIST
         7
         2         3
*SET_NODE_LIST_GENERATE
         8
         1         3
*END
)");
    const MeshData m = read_lsdyna(path);
    ASSERT_EQ(m.nodes.size(), 6U);
    ASSERT_EQ(m.triangles.size(), 4U);
    EXPECT_DOUBLE_EQ(area_and_check_normals(m), 2.0);
    using V = std::vector<Index>;
    EXPECT_EQ(m.node_sets.at("clamp"), (V{0, 3}));
    EXPECT_EQ(m.node_sets.at("node_set_8"), (V{0, 1, 2}));
    EXPECT_EQ(m.element_sets.at("shell_set_7"), (V{2, 3}));
    EXPECT_EQ(m.node_sets.at("shell_set_7"), (V{1, 2, 4, 5}));
    EXPECT_EQ(m.element_sets.at("part_1"), (V{0, 1}));
    EXPECT_EQ(m.element_sets.at("part_2"), (V{2, 3}));
}

// *INCLUDE files (relative to the including file, nested, each with its own line numbers in the
// messages), the long format, *END inside an include, and *SET_PART_LIST as the element and
// node set of its parts; node numbers kept in MeshData::node_tag.
TEST(LsDynaReader, FollowsIncludesAndReadsPartSets) {
    const TempDir dir;
    std::filesystem::create_directories(dir.folder() / "mesh");
    (void)dir.write("mesh/nodes.k", R"(*NODE +
                  11                 0.0                 0.0                 0.0
                  12                 1.0                 0.0                 0.0
*END
*NODE
this line is after *END: never read
)");
    (void)dir.write("mesh/shells.k", R"(*INCLUDE
nodes.k
*NODE
      13             0.0             1.0             0.0
      14             1.0             1.0             0.0
*ELEMENT_SHELL
       1       1      11      12      14      14
       2       2      11      14      13      13
)");
    const std::string path = dir.write("deck.k", R"(*KEYWORD
*INCLUDE
mesh/shells.k
*SET_PART_LIST
         5
         2         1
*END
)");
    const MeshData m = read_lsdyna(path);
    using V = std::vector<Index>;
    ASSERT_EQ(m.triangles.size(), 2U);
    EXPECT_EQ(m.node_tag, (std::vector<std::int64_t>{11, 12, 13, 14}));
    EXPECT_EQ(m.element_sets.at("part_set_5"), (V{0, 1}));
    EXPECT_EQ(m.node_sets.at("part_set_5"), (V{0, 1, 2, 3}));
    const std::string bad = dir.write("mesh/bad.k", "*NODE\n1,0,0,x\n");
    expect_error(read_lsdyna, bad, ":2: ", "not a finite number");
    try {  // an error in an included file names that file
        (void)read_lsdyna(dir.write("main.k", "*KEYWORD\n*INCLUDE\nmesh/bad.k\n"));
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("mesh/bad.k:2: coordinate 'x'"), std::string::npos)
            << e.what();
    }
}

// LS-DYNA errors name the file and the line.
TEST(LsDynaReader, ReportsErrorsWithLines) {
    const TempDir dir;
    const std::string nodes = "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n";
    expect_error(read_lsdyna, dir.write("a.k", nodes + "*ELEMENT_SHELL\n1,1,1,2,7,7\n"),
                 ":6: ", "refers to node 7");
    expect_error(read_lsdyna, dir.write("b.k", "*INCLUDE\nother.k\n"),
                 ":2: ", "*INCLUDE: cannot open");
    expect_error(read_lsdyna, dir.write("b2.k", "*INCLUDE\nb2.k\n"), ":2: ", "includes itself");
    expect_error(read_lsdyna, dir.write("b3.k", "*INCLUDE\n.\n"), ":2: ", "not a regular file");
    expect_error(read_lsdyna, dir.write("b4.k", "*PARAMETER\nX thick   1.0\n"),
                 ":2: ", "type R, I or C");
    expect_error(read_lsdyna, dir.write("b5.k", "*INCLUDE_TRANSFORM\nmesh.k\n"),
                 ":1: ", "not supported");
    // the formula starts in column 11: here the name field holds it all
    expect_error(read_lsdyna, dir.write("b6.k", "*PARAMETER_EXPRESSION\nR a 1+2\n"),
                 ":2: ", "not one word");
    expect_error(read_lsdyna, dir.write("c.k", nodes + "*SET_NODE_LIST\n1\n1,2,x\n"),
                 ":7: ", "expected a number");
    expect_error(read_lsdyna, dir.write("d.k", nodes + "*SET_NODE_ADD\n1\n"),
                 ":5: ", "not supported");
    expect_error(read_lsdyna, dir.write("e.k", nodes), ": ", "no shell element");
    expect_error(read_lsdyna, dir.write("f.k", nodes + "*ELEMENT_SHELL\n1,1,1,2,3,3,4\n"),
                 ":6: ", "more than 4 nodes");
    expect_error(
        read_lsdyna,
        dir.write("g.k", nodes + "*SET_NODE_LIST\n1\n1,2,9\n*ELEMENT_SHELL\n1,1,1,2,3,3\n"),
        ":6: ", "lists node 9");
}

}  // namespace
}  // namespace fpmshell
