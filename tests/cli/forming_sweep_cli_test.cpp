// spifit sweep on FE scenes (forming and cone): progress per point on stderr, sweep.csv, DIR/points/NNN/,
// plots; an input error exits 2 naming the sweep file before --out is touched.
#include "tests/cli/cli_support.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("spifit_forming_sweep_cli_" + std::to_string(::getpid()) + "_" + name); }

// A tiny indent (4 x 4 elements, 0.3 mm of travel) and a two-point penalty sweep over it.
fs::path write_files(const fs::path& dir, const std::string& extra_metric) {
  fs::create_directories(dir);
  std::ofstream(dir / "indent.toml") << "[scene]\nkind = \"indent\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                                     << "[sheet]\nelements = 4\n"
                                     << "[[path]]\nx = 0.0\ny = 0.0\nz = 0.0\n[[path]]\nx = 0.0\ny = 0.0\nz = -0.3\n"
                                     << "[solver]\ntravel_per_increment = 0.05\n";
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"indent.toml\"\nmetrics = [\"peak_fz\", \"newton_iterations\"" << extra_metric << "]\n"
                                    << "[inputs.\"contact.penalty\"]\nvalues = [10.0, 1000.0]\n";
  return dir / "sweep.toml";
}

}  // namespace

TEST(FormingSweepCli, RunsPointsInOrderWithProgress) {
  const fs::path dir = temp("ok");
  fs::remove_all(dir);
  const fs::path sweep = write_files(dir, "");
  const fs::path out = dir / "out";
  const auto r = spifit::test::run_spifit("sweep " + sweep.string() + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("point 1/2: contact.penalty=10 -> ok in "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("point 2/2: contact.penalty=1000 -> ok in "), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("2 points (0 failed)"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(out / "points" / "000" / "force.csv"));
  EXPECT_TRUE(fs::exists(out / "points" / "001" / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "sensitivities.csv"));  // forming default: no sensitivities
  std::ifstream f(out / "sweep.csv");
  std::string header;
  std::getline(f, header);
  EXPECT_EQ(header, "contact.penalty,peak_fz,newton_iterations,wall_seconds,ok");
  fs::remove_all(dir);
}

TEST(FormingSweepCli, WindowMetricWithoutWindowExitsTwo) {
  const fs::path dir = temp("bad");
  fs::remove_all(dir);
  const fs::path sweep = write_files(dir, ", \"mean_fz\"");
  const fs::path out = dir / "out";
  const auto r = spifit::test::run_spifit("sweep " + sweep.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(sweep.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("sweep.metrics"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

// A cone sweep over friction: the steady-state metrics over a contour range, one run per point
// in DIR/points/NNN/ (a one-contour cone on a coarse 90 deg pie, about a second a point).
TEST(ConeSweepCli, FrictionSweepOfACone) {
  const fs::path dir = temp("cone");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "cone.toml") << "[scene]\nkind = \"cone\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                                   << "[cone]\nwall_angle = 45.0\nstepdown = 0.5\ncontours = 1\ntop_radius = 12.0\npie_angle = 90.0\n"
                                   << "[sheet]\nthickness = 1.0\nelements_per_45deg = 6\nthickness_points = 3\n"
                                   << "[solver]\ntravel_per_increment = 0.5\n";
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"cone.toml\"\nmetrics = [\"steady_ftheta\", \"steady_fz\", \"contours_completed\"]\n"
                                    << "contours = [1, 1]\n[inputs.\"contact.friction\"]\nvalues = [0.0, 0.3]\n";
  const fs::path out = dir / "out";
  const auto r = spifit::test::run_spifit("sweep " + (dir / "sweep.toml").string() + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("point 2/2: contact.friction=0.3 -> ok in "), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out / "points" / "001" / "contours.csv"));
  std::ifstream f(out / "sweep.csv");
  std::string header, row0, row1;
  std::getline(f, header);
  std::getline(f, row0);
  std::getline(f, row1);
  EXPECT_EQ(header, "contact.friction,steady_ftheta,steady_fz,contours_completed,wall_seconds,ok");
  auto values = [](const std::string& line) {
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) v.push_back(std::stod(c));
    return v;
  };
  const auto a = values(row0), b = values(row1);
  ASSERT_EQ(a.size(), 6u);
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(a[3], 1.0);
  EXPECT_EQ(b[5], 1.0);
  // Friction drags the tool back: Ftheta (< 0, against the motion) grows in magnitude with mu.
  EXPECT_LT(b[1], a[1]);
  EXPECT_GT(b[2], 0.0);
  // A contour metric without a contour range, and a window on a cone: input errors (exit 2).
  std::ofstream(dir / "bad.toml") << "[sweep]\nscene = \"cone.toml\"\nmetrics = [\"steady_fz\"]\n[inputs.\"contact.friction\"]\nvalues = [0.1]\n";
  auto e = spifit::test::run_spifit("sweep " + (dir / "bad.toml").string() + " --out " + (dir / "bad_out").string());
  EXPECT_EQ(e.code, 2);
  EXPECT_NE(e.err.find("sweep.metrics"), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("contours = [from, to]"), std::string::npos) << e.err;
  fs::remove_all(dir);
}
