// VTU/PVD output: structure, sizes, round-trip of the numbers, and size errors.
#include "tests/support/temp_files.hpp"
#include "forward/mesh/vtu_writer.hpp"
#include "forward/mesh/square_sheet.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace spifit;

namespace {
int count(const std::string& s, const std::string& what) {
  int n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}
}  // namespace

TEST(Vtu, StructureAndValues) {
  const auto m = mesh::square_sheet({2.0, 1.0, 2, 1, false, 1.0, 1.0, 0, {}});  // 6 nodes, 2 quads
  mesh::VtuFrame f;
  mesh::VtuField thick{"thickness", 1, {1.2, 1.2, 1.1, 1.2, 1.2, 0.123456789012345678}};
  mesh::VtuField disp{"displacement", 3, std::vector<double>(18, 0.0)};
  disp.values[17] = -2.5;
  mesh::VtuField eqps{"eqps", 1, {0.0, 0.25}};
  f.point_data = {thick, disp};
  f.cell_data = {eqps};
  const std::string v = mesh::vtu_text(m, f);
  EXPECT_NE(v.find("NumberOfPoints=\"6\" NumberOfCells=\"2\""), std::string::npos);
  EXPECT_NE(v.find("Name=\"thickness\" NumberOfComponents=\"1\""), std::string::npos);
  EXPECT_NE(v.find("Name=\"displacement\" NumberOfComponents=\"3\""), std::string::npos);
  EXPECT_NE(v.find("0.12345678901234568"), std::string::npos);  // 17 significant digits
  EXPECT_NE(v.find(" 0 1 4 3 1 2 5 4"), std::string::npos);      // connectivity of the two quads
  EXPECT_EQ(count(v, "<DataArray"), count(v, "</DataArray>"));
  f.cell_data[0].values.push_back(1.0);
  EXPECT_THROW(mesh::vtu_text(m, f), std::invalid_argument);
}

TEST(Vtu, CollectionListsEveryStep) {
  const fs::path dir = fs::temp_directory_path() / ("spifit_vtu_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto m = mesh::square_sheet({1.0, 1.0, 2, 2, false, 1.0, 1.0, 0, {}});
  mesh::PvdCollection pvd(dir, "indent");
  for (int s = 0; s < 3; ++s) pvd.write_step(0.5 * s, m, {});
  const std::string pvd_text = test::slurp(dir / "indent.pvd");
  EXPECT_EQ(count(pvd_text, "<DataSet"), 3);
  EXPECT_NE(pvd_text.find("timestep=\"1\" part=\"0\" file=\"indent_000002.vtu\""), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "indent_000000.vtu"));
  fs::remove_all(dir);
}
