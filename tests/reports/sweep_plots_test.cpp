// Sweep plots: one SVG per metric plus run time, when gnuplot is available.
#include "reports/plot.hpp"
#include "reports/sweep_plots.hpp"
#include "reports/sweep_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;
using namespace spifit::reports;

TEST(SweepPlots, OneSvgPerMetric) {
  if (find_executable("gnuplot").empty()) GTEST_SKIP() << "gnuplot not on PATH";
  const fs::path dir = fs::temp_directory_path() / ("spifit_sweep_plots_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  SweepTable t;
  t.inputs = {"hill.N", "swift.n"};
  t.metrics = {"r_value", "final_stress"};
  for (double a : {2.5, 3.0, 3.5}) {
    for (double b : {0.18, 0.21}) {
      t.input_values.push_back({a, b});
      t.metric_values.push_back({a / 3.0, b == 0.18 ? NAN : 100.0 * b});  // a missing metric is left out
      t.wall_seconds.push_back(1e-3);
      t.ok.push_back(true);
    }
  }
  const auto warnings = render_sweep_plots(dir, t);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  for (const char* f : {"sweep_r_value.svg", "sweep_final_stress.svg", "sweep_wall_seconds.svg"}) {
    ASSERT_TRUE(fs::exists(dir / "plots" / f)) << f;
    EXPECT_GT(fs::file_size(dir / "plots" / f), 1000u) << f;
  }
  fs::remove_all(dir);
}

// Forming sweeps: a penalty 1e1..1e7 gets a log x axis; a friction 0..0.15 (0 included) does not.
TEST(SweepPlots, LogXForWidePositiveFirstInput) {
  EXPECT_TRUE(sweep_log_x({10.0, 1e3, 1e5, 1e7}));
  EXPECT_FALSE(sweep_log_x({0.0, 0.05, 0.1, 0.15}));
  EXPECT_FALSE(sweep_log_x({2.5, 3.0, 4.5}));
  EXPECT_FALSE(sweep_log_x({}));
  if (find_executable("gnuplot").empty()) GTEST_SKIP() << "gnuplot not on PATH";
  const fs::path dir = fs::temp_directory_path() / ("spifit_sweep_plots_log_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  SweepTable t;
  t.inputs = {"contact.penalty"};
  t.metrics = {"peak_fz", "newton_iterations"};
  for (double kp : {10.0, 1e3, 1e5, 1e7}) {
    t.input_values.push_back({kp});
    t.metric_values.push_back({294.0 * kp / (kp + 100.0), 20.0 + std::log10(kp)});
    t.wall_seconds.push_back(1.0);
    t.ok.push_back(true);
  }
  const auto warnings = render_sweep_plots(dir, t);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  for (const char* stem : {"sweep_peak_fz", "sweep_newton_iterations", "sweep_wall_seconds"}) {
    ASSERT_TRUE(fs::exists(dir / "plots" / (std::string(stem) + ".svg"))) << stem;
    std::ifstream gp(dir / "plots" / "src" / (std::string(stem) + ".gp"));
    const std::string script((std::istreambuf_iterator<char>(gp)), std::istreambuf_iterator<char>());
    EXPECT_NE(script.find("set logscale x"), std::string::npos) << stem;
  }
  fs::remove_all(dir);
}

// The sweep report: units in the table's header and the plots' axes, failed points named.
TEST(SweepReport, TablesAndAxesCarryUnitsAndFailuresAreNamed) {
  const fs::path dir = fs::temp_directory_path() / ("spifit_sweep_report_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  SweepTable t;
  t.inputs = {"contact.penalty"};
  t.input_units = {"N/mm^3"};
  t.metrics = {"peak_fz", "newton_iterations"};
  t.metric_units = {"N", ""};
  for (double kp : {1e2, 1e3, 1e4}) {
    t.input_values.push_back({kp});
    t.metric_values.push_back({0.3 * kp, 40.0});
    t.wall_seconds.push_back(0.5);
    t.ok.push_back(kp < 1e4);
  }
  const auto r = render_sweep_report(dir, "penalty", t, {"", "", "increment failed at the minimum increment"});
  std::ifstream in(r.markdown);
  const std::string md((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("| point | contact.penalty [N/mm^3] | peak_fz [N] | newton_iterations | wall time [s] |"), std::string::npos) << md;
  EXPECT_NE(md.find("1 of 3 points failed"), std::string::npos) << md;
  EXPECT_NE(md.find("point 3: increment failed at the minimum increment"), std::string::npos) << md;
  if (!find_executable("gnuplot").empty()) {
    std::ifstream gp(dir / "plots" / "src" / "sweep_peak_fz.gp");
    const std::string script((std::istreambuf_iterator<char>(gp)), std::istreambuf_iterator<char>());
    EXPECT_NE(script.find("set xlabel 'contact.penalty [N/mm^3]'"), std::string::npos) << script;
    EXPECT_NE(script.find("set ylabel 'peak_fz [N]'"), std::string::npos) << script;
    EXPECT_NE(md.find("![peak_fz [N] against contact.penalty [N/mm^3]](plots/sweep_peak_fz.svg)"), std::string::npos) << md;
  }
  fs::remove_all(dir);
}
