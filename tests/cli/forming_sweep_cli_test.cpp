// spifit sweep on FE scenes (forming and cone): progress per point on stderr, sweep.csv, DIR/points/NNN/,
// plots; a cone's steady-state metrics equal the means of its contours.csv; a point that fails
// is reported and the sweep goes on; an input error exits 2 naming the sweep file before --out
// is touched.
#include "tests/cli/cli_support.hpp"
#include "tests/support/csv_rows.hpp"
#include "tests/support/same_outputs.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <cmath>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

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
  const fs::path dir = spifit::test::fresh_temp_path("ok");
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
  const fs::path dir = spifit::test::fresh_temp_path("bad");
  const fs::path sweep = write_files(dir, ", \"mean_fz\"");
  const fs::path out = dir / "out";
  const auto r = spifit::test::run_spifit("sweep " + sweep.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(sweep.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("sweep.metrics"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

namespace {

// Writes SWEEP (the [sweep] table and its inputs) beside a one-contour small tiny cone (top
// radius 12 mm, 72 elements, about a second a point) in DIR and runs it into DIR/NAME.
spifit::test::CliResult run_cone_sweep(const fs::path& dir, const std::string& name, const std::string& sweep) {
  fs::create_directories(dir);
  if (!fs::exists(dir / "cone.toml")) spifit::test::write_tiny_cone(dir / "cone.toml", "", spifit::test::small_tiny_cone(1));
  std::ofstream(dir / (name + ".toml")) << "[sweep]\nscene = \"cone.toml\"\n" << sweep;
  return spifit::test::run_spifit("sweep " + (dir / (name + ".toml")).string() + " --out " + (dir / name).string());
}

bool same(double a, double b, double rel) { return std::abs(a - b) <= rel * std::abs(b); }

}  // namespace

// A cone sweep over friction: the steady-state metrics over the contour range [1, 1] are the
// central-third means of contour 1 in each point's own contours.csv (DIR/points/NNN/).
TEST(ConeSweepCli, FrictionSweepOfACone) {
  const fs::path dir = spifit::test::fresh_temp_path("cone");
  const auto r = run_cone_sweep(dir, "out", "metrics = [\"steady_ftheta\", \"steady_fz\", \"contours_completed\"]\n"
                                           "contours = [1, 1]\n[inputs.\"contact.friction\"]\nvalues = [0.0, 0.3]\n");
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path out = dir / "out";
  EXPECT_NE(r.err.find("point 1/2: contact.friction=0 -> ok in "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("point 2/2: contact.friction=0.3 -> ok in "), std::string::npos) << r.err;
  std::ifstream f(out / "sweep.csv");
  std::string header;
  std::getline(f, header);
  EXPECT_EQ(header, "contact.friction,steady_ftheta,steady_fz,contours_completed,wall_seconds,ok");
  const auto rows = spifit::test::read_csv_rows(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 2u);
  const double friction[2] = {0.0, 0.3};
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_EQ(rows[i].size(), 6u);
    EXPECT_EQ(rows[i][0], friction[i]);
    EXPECT_EQ(rows[i][3], 1.0);  // contours_completed
    EXPECT_EQ(rows[i][5], 1.0);  // ok
    // contours.csv: stage, contour, samples, Fx, Fy, Fz, Fr, Ftheta (central-third means).
    const auto means = spifit::test::read_csv_rows(out / "points" / ("00" + std::to_string(i)) / "contours.csv");
    ASSERT_EQ(means.size(), 1u);
    ASSERT_EQ(means[0].size(), 8u);
    EXPECT_EQ(means[0][1], 1.0);
    EXPECT_TRUE(same(rows[i][1], means[0][7], 1e-12)) << rows[i][1] << " vs contours.csv Ftheta " << means[0][7];
    EXPECT_TRUE(same(rows[i][2], means[0][5], 1e-12)) << rows[i][2] << " vs contours.csv Fz " << means[0][5];
  }
  // Friction drags the tool back: Ftheta (< 0, against the motion) grows in magnitude with mu.
  EXPECT_LT(rows[1][1], rows[0][1]);
  EXPECT_GT(rows[1][2], 0.0);
  fs::remove_all(dir);
}

// The documented edges of a cone sweep's contour range and window (docs/reference/file-formats.md, "Sweep
// file"): a contour metric without a contour range and a window on a cone are input
// errors (exit 2, the key named, --out untouched); a range the run never reaches gives NaN, the
// run being fine.
TEST(ConeSweepCli, ContourRangeAndWindowEdges) {
  const fs::path dir = spifit::test::fresh_temp_path("cone_edges");
  auto e = run_cone_sweep(dir, "no_range", "metrics = [\"steady_fz\"]\n[inputs.\"contact.friction\"]\nvalues = [0.1]\n");
  EXPECT_EQ(e.code, 2);
  EXPECT_NE(e.err.find((dir / "no_range.toml").string()), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("sweep.metrics"), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("contours = [from, to]"), std::string::npos) << e.err;
  EXPECT_FALSE(fs::exists(dir / "no_range"));
  e = run_cone_sweep(dir, "window", "metrics = [\"steady_fz\"]\ncontours = [1, 1]\nwindow = [0.0, 10.0]\n"
                                    "[inputs.\"contact.friction\"]\nvalues = [0.1]\n");
  EXPECT_EQ(e.code, 2);
  EXPECT_NE(e.err.find((dir / "window.toml").string()), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("sweep.window"), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("only for scene kinds with metrics over a travel window (indent, indent_line, line)"), std::string::npos) << e.err;
  EXPECT_FALSE(fs::exists(dir / "window"));

  // Contours 2 to 3 of a one-contour cone.
  const auto r = run_cone_sweep(dir, "unreached", "metrics = [\"steady_fz\", \"steady_fr_over_fz\", \"contours_completed\"]\n"
                                                  "contours = [2, 3]\n[inputs.\"contact.friction\"]\nvalues = [0.0]\n");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = spifit::test::read_csv_rows(dir / "unreached" / "sweep.csv");
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_EQ(rows[0].size(), 6u);
  EXPECT_TRUE(std::isnan(rows[0][1])) << rows[0][1];
  EXPECT_TRUE(std::isnan(rows[0][2])) << rows[0][2];
  EXPECT_EQ(rows[0][3], 1.0);  // contours_completed
  EXPECT_EQ(rows[0][5], 1.0);  // ok: the run itself is fine
  fs::remove_all(dir);
}

// A point that fails at run time (docs/reference/cli.md "sweep", docs/reference/file-formats.md): the small tiny
// cone at force_tolerance 1e-12 fails after 9 increments (about 0.3 s), at 1e-4 it runs. The
// failed point is reported on stderr with its message, has ok = 0 and NaN force metrics but
// keeps its counts (those of its own summary.json), summary.json counts it, the exit code is 0
// and the next point runs.
TEST(ConeSweepCli, FailingPointIsReportedNotFatal) {
  const fs::path dir = spifit::test::fresh_temp_path("cone_fail");
  const auto r = run_cone_sweep(dir, "out", "metrics = [\"peak_fz\", \"steady_fz\", \"increments\", \"newton_iterations\", \"contours_completed\"]\n"
                                           "contours = [1, 1]\n[inputs.\"solver.force_tolerance\"]\nvalues = [1e-12, 1e-4]\n");
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path out = dir / "out";
  const auto failed = spifit::test::read_summary(out / "points" / "000");
  const auto passed = spifit::test::read_summary(out / "points" / "001");
  EXPECT_EQ(failed["status"], "failed");
  EXPECT_EQ(passed["status"], "ok");
  const std::string message = failed.value("message", "");
  EXPECT_FALSE(message.empty());
  EXPECT_NE(r.err.find("point 1/2: solver.force_tolerance=1e-12 -> failed in "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" s: " + message), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("point 2/2: solver.force_tolerance=0.0001 -> ok in "), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("2 points (1 failed)"), std::string::npos) << r.out;
  const auto summary = spifit::test::read_summary(out);
  EXPECT_EQ(summary["status"], "ok");
  EXPECT_EQ(summary["points"].get<int>(), 2);
  EXPECT_EQ(summary["failed_points"].get<int>(), 1);

  const auto rows = spifit::test::read_csv_rows(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 2u);
  ASSERT_EQ(rows[0].size(), 8u);
  ASSERT_EQ(rows[1].size(), 8u);
  // The failed point: no force metrics, the counts of what was done.
  EXPECT_EQ(rows[0][0], 1e-12);
  EXPECT_TRUE(std::isnan(rows[0][1])) << rows[0][1];  // peak_fz
  EXPECT_TRUE(std::isnan(rows[0][2])) << rows[0][2];  // steady_fz
  EXPECT_EQ(rows[0][3], 9.0);                         // increments
  EXPECT_EQ(rows[0][3], failed["increments"].get<double>());
  EXPECT_EQ(rows[0][4], failed["newton_iterations"].get<double>());
  EXPECT_GT(rows[0][4], rows[0][3]);
  EXPECT_EQ(rows[0][5], 0.0);  // contours_completed
  EXPECT_EQ(rows[0][7], 0.0);  // ok
  // The next point ran through.
  EXPECT_EQ(rows[1][0], 1e-4);
  EXPECT_TRUE(same(rows[1][1], passed["peak_force"][2].get<double>(), 1e-12)) << rows[1][1];
  EXPECT_GT(rows[1][1], 0.0);
  // steady_fz over contours [1, 1]: contour 1's central-third mean Fz in the point's contours.csv.
  const auto contours = spifit::test::read_csv_rows(out / "points" / "001" / "contours.csv");
  ASSERT_EQ(contours.size(), 1u);
  EXPECT_TRUE(same(rows[1][2], contours[0][5], 1e-12)) << rows[1][2] << " vs " << contours[0][5];
  EXPECT_EQ(rows[1][3], passed["increments"].get<double>());
  EXPECT_EQ(rows[1][4], passed["newton_iterations"].get<double>());
  EXPECT_EQ(rows[1][5], 1.0);
  EXPECT_EQ(rows[1][7], 1.0);

  // `spifit report DIR` renders the same report from sweep.csv and summary.json, the failed
  // point's message and NaN metrics included; a sweep summary without its table is named.
  const std::string md = spifit::test::slurp(out / "report.md"), html = spifit::test::slurp(out / "report.html");
  EXPECT_NE(md.find(message.substr(0, 40)), std::string::npos) << md;
  fs::remove(out / "report.md");
  const auto again = spifit::test::run_spifit("report --no-plots " + out.string());
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(spifit::test::slurp(out / "report.md"), md);
  EXPECT_EQ(spifit::test::slurp(out / "report.html"), html);
  auto old_summary = summary;
  old_summary.erase("metrics");
  std::ofstream(out / "summary.json") << old_summary.dump(2);
  const auto bad = spifit::test::run_spifit("report " + out.string());
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("summary.json: metrics: missing"), std::string::npos) << bad.err;
  fs::remove_all(dir);
}
