#include "symcontact/io/pvd_writer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "support/temp_folder.hpp"

namespace symcontact {
namespace {

namespace fs = std::filesystem;

TEST(PvdWriter, ContentAfterSeveralAdds) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  PvdCollection pvd((dir / "run.pvd").string());
  pvd.add(0.0, 0, "run/body0_000000.vtu", "block");
  pvd.add(0.0, 1, "run/body1_000000.vtu", "punch");
  pvd.write();
  EXPECT_EQ(testing::read_text(pvd.path()),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\">\n"
            "  <Collection>\n"
            "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"run/body0_000000.vtu\" name=\"block\"/>\n"
            "    <DataSet timestep=\"0\" group=\"\" part=\"1\" file=\"run/body1_000000.vtu\" name=\"punch\"/>\n"
            "  </Collection>\n"
            "</VTKFile>\n");

  pvd.add(0.25, 0, "run/body0_000001.vtu", "block");
  pvd.add(0.25, 1, "run/body1_000001.vtu");  // no name
  pvd.write();                               // rewrites the whole file
  EXPECT_EQ(pvd.size(), 4u);
  EXPECT_EQ(testing::read_text(pvd.path()),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\">\n"
            "  <Collection>\n"
            "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"run/body0_000000.vtu\" name=\"block\"/>\n"
            "    <DataSet timestep=\"0\" group=\"\" part=\"1\" file=\"run/body1_000000.vtu\" name=\"punch\"/>\n"
            "    <DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"run/body0_000001.vtu\" name=\"block\"/>\n"
            "    <DataSet timestep=\"0.25\" group=\"\" part=\"1\" file=\"run/body1_000001.vtu\"/>\n"
            "  </Collection>\n"
            "</VTKFile>\n");
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  EXPECT_EQ(n, 1u);  // no temporary files left
}

TEST(PvdWriter, EmptyCollectionAndEscaping) {
  const testing::TempFolder folder;
  const fs::path& dir = folder.path();
  PvdCollection pvd((dir / "empty.pvd").string());
  pvd.write();
  EXPECT_EQ(testing::read_text(pvd.path()),
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n"
            "  </Collection>\n</VTKFile>\n");
  pvd.add(1e-3, 2, "a&b.vtu", "\"quoted\" <name>");
  pvd.write();
  EXPECT_NE(testing::read_text(pvd.path()).find("timestep=\"0.001\" group=\"\" part=\"2\" file=\"a&amp;b.vtu\" "
                                      "name=\"&quot;quoted&quot; &lt;name&gt;\"/>"),
            std::string::npos);
}

TEST(PvdWriter, RejectsBadEntries) {
  PvdCollection pvd("unused.pvd");
  EXPECT_THROW(pvd.add(std::numeric_limits<double>::quiet_NaN(), 0, "a.vtu"), std::invalid_argument);
  EXPECT_THROW(pvd.add(0.0, -1, "a.vtu"), std::invalid_argument);
  EXPECT_THROW(pvd.add(0.0, 0, ""), std::invalid_argument);
  EXPECT_EQ(pvd.size(), 0u);
}

}  // namespace
}  // namespace symcontact
