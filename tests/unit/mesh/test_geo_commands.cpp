#include "symcontact/mesh/geo_commands.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "support/temp_folder.hpp"
#include "symcontact/core/error.hpp"

using namespace symcontact;

namespace {

namespace fs = std::filesystem;

class GeoCommands : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) const { return folder_.write(name, text).string(); }
  /// The key ("line L") of the error check_geo_commands() throws for `path`, or "none".
  static std::string refused_at(const std::string& path) {
    try {
      check_geo_commands(path);
    } catch (const InputError& e) {
      return e.key();
    }
    return "none";
  }
  const symcontact::testing::TempFolder folder_;
  const fs::path& dir_ = folder_.path();
};

TEST_F(GeoCommands, CommandsOutsideCommentsAndStringsAreRefusedWithTheirLine) {
  EXPECT_EQ(refused_at(write("a.geo", "Point(1) = {0, 0, 0};\nSystemCall \"rm -rf x\";\n")), "line 2");
  EXPECT_EQ(refused_at(write("b.geo", "/* a\nb */ System \"ls\";\n")), "line 2");
  EXPECT_EQ(refused_at(write("c.geo", "x = 1;\n\n\nNonBlockingSystemCall \"ls\";")), "line 4");
  EXPECT_EQ(refused_at(write("d.geo", "OnelabRun(\"a\", \"b\");")), "line 1");
}

TEST_F(GeoCommands, CommentsStringsAndLongerNamesAreNotCommands) {
  EXPECT_EQ(refused_at(write("ok.geo", "// SystemCall \"ls\";\n/* System */\nPrintf(\"SystemCall\");\n"
                                       "SystemCalls = 2;\nlc = 0.1; // Shell\n")),
            "none");
}

TEST_F(GeoCommands, IncludedFilesAreScannedAndComputedNamesRefused) {
  write("inner.geo", "\n\nSystemCall \"ls\";\n");
  try {
    check_geo_commands(write("outer.geo", "Include \"inner.geo\";\n"));
    FAIL() << "the included command was not found";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir_ / "inner.geo").string());
    EXPECT_EQ(e.key(), "line 3");
  }
  EXPECT_EQ(refused_at(write("computed.geo", "Include StrCat(\"in\", \"ner.geo\");\n")), "line 1");
  write("mesh.msh", "$MeshFormat\n");  // merged meshes are data, not scripts
  EXPECT_EQ(refused_at(write("merge.geo", "Merge \"mesh.msh\";\n")), "none");
  EXPECT_EQ(refused_at(write("self.geo", "Include \"self.geo\";\n")), "line 1");  // nesting limit
}

TEST_F(GeoCommands, DefinedConstantsAreTheNamesInsideDefineConstant) {
  write("sizes.geo", "DefineConstant[ h = 0.1 ];\n");
  const std::string path = write("constants.geo",
                                 "DefineConstant[ n = 4, lc = {0.5, Name \"Parameters/lc\", Min 0.1, Max 1},\n"
                                 "  w = {2, Choices{1 = \"a\", 2 = \"b\"}} ];\n"
                                 "m = 3;  // a plain assignment is not a constant\n"
                                 "// DefineConstant[ commented = 1 ];\n"
                                 "Include \"sizes.geo\";\n"
                                 "Printf(\"DefineConstant[ in_string = 1 ]\");\n");
  EXPECT_EQ(geo_defined_constants(path), (std::set<std::string>{"h", "lc", "n", "w"}));
}

TEST(GeoIdentifier, LettersDigitsAndUnderscoreNotFirstDigit) {
  EXPECT_TRUE(is_geo_identifier("h"));
  EXPECT_TRUE(is_geo_identifier("_n2"));
  EXPECT_TRUE(is_geo_identifier("Mesh_size"));
  EXPECT_FALSE(is_geo_identifier(""));
  EXPECT_FALSE(is_geo_identifier("2h"));
  EXPECT_FALSE(is_geo_identifier("h-1"));
  EXPECT_FALSE(is_geo_identifier("a.b"));
  EXPECT_FALSE(is_geo_identifier("h "));
}

}  // namespace
