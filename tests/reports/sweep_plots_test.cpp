// Sweep plots: one SVG per metric plus run time, when gnuplot is available.
#include "reports/plot.hpp"
#include "reports/sweep_plots.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

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
