// Tests of the structural check of .msh files (src/symcontact/mesh/msh_validation.hpp): the files Gmsh
// writes pass, and every kind of malformed structure is an InputError naming the file and the line,
// before Gmsh's parser sees it (the fuzz target fuzz/fuzz_msh_reader.cpp explores the rest).

#include "symcontact/mesh/msh_validation.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/problem_snippet.hpp"
#include "support/temp_folder.hpp"
#include "symcontact/core/error.hpp"
#include "symcontact/mesh/gmsh_io.hpp"

namespace symcontact {
namespace {

/// tests/data/meshes/unit_square.msh (MSH 4.1): two triangles, groups bottom, top, square.
const std::string kMsh4 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
3
1 1 "bottom"
1 2 "top"
2 3 "square"
$EndPhysicalNames
$Entities
0 2 1 0
1 0 0 0 1 0 0 1 1 0
2 0 1 0 1 1 0 1 2 0
1 0 0 0 1 1 0 1 3 0
$EndEntities
$Nodes
1 4 1 4
2 1 0 4
1
2
3
4
0 0 0
1 0 0
1 1 0
0 1 0
$EndNodes
$Elements
3 4 1 4
1 1 1 1
1 1 2
1 2 1 1
2 3 4
2 1 2 2
3 1 2 3
4 1 3 4
$EndElements
)";

/// The same mesh in MSH 2.2.
const std::string kMsh2 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
3
1 1 "bottom"
1 2 "top"
2 3 "square"
$EndPhysicalNames
$Nodes
4
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
$EndNodes
$Elements
4
1 1 2 1 1 1 2
2 1 2 2 2 3 4
3 2 2 3 1 1 2 3
4 2 2 3 1 1 3 4
$EndElements
)";

using testing::InputErrorCase;
using testing::replaced;

TEST(MshValidation, FilesAsGmshWritesThemPass) {
  EXPECT_NO_THROW(validate_msh_text(kMsh4, "mesh.msh"));
  EXPECT_NO_THROW(validate_msh_text(kMsh2, "mesh.msh"));
  EXPECT_NO_THROW(validate_msh_text(replaced(kMsh2, "\n", "\r\n"), "mesh.msh")) << "CR LF line ends";
  for (const char* name : {"unit_square.msh", "degenerate_triangle.msh"}) {
    EXPECT_NO_THROW(validate_msh_file(std::string(SYMCONTACT_TEST_DATA) + "/meshes/" + name)) << name;
  }
}

class MshValidationBadInput : public ::testing::TestWithParam<InputErrorCase> {};

TEST_P(MshValidationBadInput, IsAnInputErrorNamingTheFileAndLine) {
  const InputErrorCase& c = GetParam();
  testing::expect_input_error_case([&] { validate_msh_text(c.text, "mesh.msh"); }, c, "mesh.msh");
}

INSTANTIATE_TEST_SUITE_P(
    MshValidation, MshValidationBadInput,
    ::testing::Values(
        // the format line
        InputErrorCase{"Empty", "", "line 1", "the file is empty"},
        InputErrorCase{"NotMsh", "solid cube\nfacet normal 0 0 1\n", "line 1", "expected $MeshFormat on the first line"},
        InputErrorCase{"Binary", replaced(kMsh4, "4.1 0 8", "4.1 1 8"), "line 2", "binary .msh files are not supported"},
        InputErrorCase{"Version40", replaced(kMsh4, "4.1 0 8", "4 0 8"), "line 2", "MSH version 4 is not supported"},
        InputErrorCase{"Version3", replaced(kMsh2, "2.2 0 8", "3.0 0 8"), "line 2", "MSH version 3.0 is not supported"},
        InputErrorCase{"FormatLineShort", replaced(kMsh4, "4.1 0 8", "4.1 0"), "line 2", "expected version file-type data-size"},
        InputErrorCase{"NulByte", replaced(kMsh4, "4.1 0 8", std::string("4.1 0\0 8", 8)), "line 2", "a NUL byte"},
        // sections
        InputErrorCase{"UnknownSection", replaced(kMsh4, "$Nodes\n", "$NodeData\n1\n$EndNodeData\n$Nodes\n"), "line 16",
               "section $NodeData is not supported"},
        InputErrorCase{"PrefixOfAKnownSection", replaced(kMsh4, "$Nodes\n", "$NodesX\n$EndNodesX\n$Nodes\n"), "line 16",
               "section $NodesX is not supported"},
        InputErrorCase{"TwoNodeSections", replaced(kMsh2, "$Elements\n", "$Nodes\n0\n$EndNodes\n$Elements\n"), "line 17",
               "a second $Nodes section (the first is on line 10)"},
        InputErrorCase{"ElementsBeforeNodes", replaced(kMsh2, "$Nodes\n", "$Elements\n0\n$EndElements\n$Nodes\n"), "line 10",
               "$Elements before $Nodes"},
        InputErrorCase{"StrayLine", replaced(kMsh2, "$Nodes\n", "hello\n$Nodes\n"), "line 10",
               "expected a section header ($Name alone on its line), got \"hello\""},
        InputErrorCase{"EndWithoutStart", replaced(kMsh2, "$Nodes\n", "$EndComments\n$Nodes\n"), "line 10",
               "$EndComments without an opening $Comments"},
        InputErrorCase{"TruncatedInNodes", kMsh4.substr(0, kMsh4.find("\n1 1 0\n") + 1), "line 24",
               "the file ends inside $Nodes (expected the coordinates of node 3): is it truncated?"},
        InputErrorCase{"MissingEnd", kMsh2.substr(0, kMsh2.find("$EndElements")), "line 22",
               "the file ends inside $Elements (expected $EndElements): is it truncated?"},
        InputErrorCase{"CountTooSmall", replaced(kMsh2, "$Nodes\n4\n", "$Nodes\n3\n"), "line 15",
               "expected $EndNodes (the end of the section: is a count too small?), got \"4 0 1 0\""},
        InputErrorCase{"LongHeaderLine", replaced(kMsh2, "$Nodes\n", "$Nodes" + std::string(300, ' ') + "\n"), "line 10",
               "a line longer than 255 characters"},
        // physical names
        InputErrorCase{"UnquotedName", replaced(kMsh4, "\"top\"", "top"), "line 7", "expected the physical name in double quotes"},
        InputErrorCase{"NameDimension", replaced(kMsh4, "2 3 \"square\"", "4 3 \"square\""), "line 8",
               "expected the dimension of a physical group in [0, 3], got 4"},
        // entities
        InputErrorCase{"UndeclaredBoundingPoint", replaced(kMsh4, "1 0 0 0 1 0 0 1 1 0", "1 0 0 0 1 0 0 1 1 2 7 8"), "line 12",
               "bounding point 7 of curve 1 is not declared"},
        InputErrorCase{"BoundingListShort", replaced(kMsh4, "1 0 0 0 1 0 0 1 1 0", "1 0 0 0 1 0 0 1 1 3 7 8"), "line 12",
               "expected the bounding points (13 values), got 12"},
        InputErrorCase{"BoundingCurveNotDeclared", replaced(kMsh4, "1 0 0 0 1 1 0 1 3 0", "1 0 0 0 1 1 0 1 3 1 5"),
               "line 14", "bounding curve 5 of surface 1 is not declared"},
        InputErrorCase{"EntityBoxNotANumber", replaced(kMsh4, "1 0 0 0 1 1 0 1 3 0", "1 0 0 0 x 1 0 1 3 0"), "line 14",
               "expected a coordinate (a number), got \"x\""},
        // nodes
        InputErrorCase{"NodeBlocksDoNotAddUp", replaced(kMsh4, "1 4 1 4\n2 1 0 4", "1 5 1 5\n2 1 0 4"), "line 17",
               "the node blocks hold 4 nodes, the $Nodes header announced 5"},
        InputErrorCase{"ElementBlocksDoNotAddUp", replaced(kMsh4, "3 4 1 4\n", "3 5 1 5\n"), "line 29",
               "the element blocks hold 4 elements, the $Elements header announced 5"},
        InputErrorCase{"NodeBlockTooLarge", replaced(kMsh4, "2 1 0 4", "2 1 0 9"), "line 18",
               "expected the number of nodes in the block in [0, 4], got 9"},
        InputErrorCase{"NodeTagOutsideRange", replaced(kMsh4, "1\n2\n3\n4\n", "1\n2\n3\n5\n"), "line 22",
               "expected a node tag in [1, 4], got 5"},
        InputErrorCase{"NodeTagTwice", replaced(kMsh2, "4 0 1 0", "3 0 1 0"), "line 15", "node 3 is defined twice"},
        InputErrorCase{"NodeTagZero", replaced(kMsh2, "1 0 0 0\n", "0 0 0 0\n"), "line 12",
               "expected a node tag in [1, 2147483647], got 0"},
        InputErrorCase{"NanCoordinate", replaced(kMsh4, "\n1 1 0\n", "\n1 nan 0\n"), "line 25",
               "node 3: the y coordinate is not a finite number (got \"nan\")"},
        InputErrorCase{"InfCoordinate", replaced(kMsh2, "2 1 0 0", "2 inf 0 0"), "line 13",
               "node 2: the x coordinate is not a finite number (got \"inf\")"},
        InputErrorCase{"CoordinateMissing", replaced(kMsh2, "2 1 0 0", "2 1 0"), "line 13", "expected node tag x y z (4 values), got 3"},
        InputErrorCase{"NodeOfUndeclaredEntity", replaced(kMsh4, "2 1 0 4", "2 9 0 4"), "line 18",
               "entity (dimension 2, tag 9) is not declared in $Entities"},
        InputErrorCase{"HugeCount", replaced(kMsh2, "$Nodes\n4\n", "$Nodes\n99999999999\n"), "line 11",
               "expected the number of nodes in [0, 2147483647], got 99999999999"},
        // elements
        InputErrorCase{"UnknownElementType", replaced(kMsh2, "3 2 2 3 1 1 2 3", "3 77 2 3 1 1 2 3"), "line 21",
               "element 3: unknown element type 77"},
        InputErrorCase{"ElementNodeUndefined", replaced(kMsh2, "4 2 2 3 1 1 3 4", "4 2 2 3 1 1 3 9"), "line 22",
               "element 4 refers to node 9, which $Nodes does not define"},
        InputErrorCase{"ElementTooFewNodes", replaced(kMsh4, "4 1 3 4", "4 1 3"), "line 36",
               "expected an element tag and 3 node tags (4 values), got 3"},
        InputErrorCase{"ElementTypeOfTheWrongDimension", replaced(kMsh4, "2 1 2 2", "2 1 4 2"), "line 34",
               "element type 4 has dimension 3, but the block's entity has dimension 2"},
        InputErrorCase{"PartitionCountBeyondTags", replaced(kMsh2, "3 2 2 3 1 1 2 3", "3 2 3 3 1 5 1 2 3"), "line 21",
               "expected the number of partitions in [0, 0], got 5"},
        InputErrorCase{"NegativeTagCount", replaced(kMsh2, "3 2 2 3 1 1 2 3", "3 2 -2 3 1 1 2 3"), "line 21",
               "expected the number of tags in [0, 64], got -2"}),
    [](const ::testing::TestParamInfo<InputErrorCase>& case_info) { return case_info.param.name; });

TEST(MshValidation, ReadMeshFileRejectsBeforeGmshReads) {
  // The same fault through read_mesh_file(): an InputError naming the file and the line.
  const testing::TempFolder folder;
  const std::string path = folder.write("nan_node.msh", replaced(kMsh4, "\n1 1 0\n", "\n1 nan 0\n")).string();
  MeshReadOptions opt;
  try {
    read_mesh_file(path, opt);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.key(), "line 25");
    EXPECT_NE(e.message().find("node 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace symcontact
