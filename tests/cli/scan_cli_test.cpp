// `spifit scan`: a synthetic cloud of a 50 deg cone's outer surface becomes section.csv (bin
// means on the surface, shifted by T/2), summary.json and a plot; malformed clouds and options
// exit with 2 and one line naming file, line (or option) and value, before --out is touched.
#include "tests/cli/cli_support.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

namespace fs = std::filesystem;

namespace spifit::test {
namespace {

double cone50_z(double r) {  // outer surface: flat bottom below r = 20, 50 deg wall to r = 40, flange
  const double t = std::tan(50.0 * std::numbers::pi / 180.0);
  return r < 20.0 ? -20.0 * t : (r < 40.0 ? -(40.0 - r) * t : 0.0);
}

TEST(ScanCli, WritesTheSectionSummaryAndPlot) {
  const fs::path cloud = temp_path("cloud.csv"), out = temp_path("out");
  {
    std::ofstream f(cloud);
    f << "# synthetic scan: 50 deg cone, noise 0.02 mm, seed 7\nx [mm],y [mm],z [mm]\n";
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> ur(0.0, 45.0), ut(0.0, 2.0 * std::numbers::pi);
    std::normal_distribution<double> noise(0.0, 0.02);
    f.precision(10);
    for (int i = 0; i < 20000; ++i) {
      const double r = ur(rng), t = ut(rng);
      f << r * std::cos(t) << "," << r * std::sin(t) << "," << cone50_z(r) + noise(rng) << "\n";
    }
  }
  fs::remove_all(out);
  const CliResult r = run_spifit("scan " + cloud.string() + " --out " + out.string() + " --bin 1 --shift-by-half-thickness 1.5");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("45 bins"), std::string::npos) << r.out;
  std::ifstream in(out / "section.csv");
  std::string line;
  int rows = 0;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      EXPECT_EQ(line, "bin_lower [mm],bin_upper [mm],points,r [mm],z [mm],std [mm],r_low [mm],z_low [mm],r_high [mm],z_high [mm],inside");
      header = true;
      continue;
    }
    std::stringstream ss(line);
    std::vector<double> v;
    for (std::string c; std::getline(ss, c, ',');) v.push_back(std::stod(c));
    ASSERT_EQ(v.size(), 11u);
    // Bin means on the surface (away from the kinks), moved up by 0.75 mm.
    if (std::abs(v[0] - 20.0) > 1.5 && std::abs(v[0] - 40.0) > 1.5) {
      EXPECT_NEAR(v[4] - 0.75, cone50_z(v[3]), 0.01) << line;
    }
    EXPECT_LT(v[7], v[4]);
    EXPECT_GT(v[9], v[4]);
    ++rows;
  }
  EXPECT_EQ(rows, 45);
  const std::string js = slurp(out / "summary.json");
  EXPECT_NE(js.find("\"status\": \"ok\""), std::string::npos);
  EXPECT_NE(js.find("\"shift\": \"vertical\""), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "plots" / "section.svg") || r.err.find("gnuplot") != std::string::npos) << r.err;
  fs::remove_all(out);
  fs::remove(cloud);
}

TEST(ScanCli, ErrorsNameFileLineAndValue) {
  const fs::path cloud = temp_path("bad.csv"), out = temp_path("bad_out");
  std::ofstream(cloud) << "x,y,z\n1,2,3\n1,2,three\n";
  fs::remove_all(out);
  CliResult r = run_spifit("scan " + cloud.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(cloud.string() + ": line 3, column z = three"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  r = run_spifit("scan " + cloud.string() + " --out " + out.string() + " --bin -1");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--bin = -1: must be > 0"), std::string::npos) << r.err;
  r = run_spifit("scan " + cloud.string() + " --out " + out.string() + " --by theta");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--by = theta"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(cloud);
}

}  // namespace
}  // namespace spifit::test
