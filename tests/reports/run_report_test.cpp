// The report of an FE run's directory: the summary and plots of a finished indent, the same of
// a partial directory (a killed run: status running, force.csv cut mid-row), and a clear error
// for a directory that is not an FE run's.
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/io/text_file.hpp"
#include "forward/scenes/forming/forming_run.hpp"
#include "forward/scenes/forming/forming_scene.hpp"
#include "reports/plot.hpp"
#include "reports/run_report.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace spifit;

namespace {

fs::path run_indent(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("spifit_run_report_" + tag + "_" + std::to_string(::getpid()));
  const scene::FormingScene s = scene::read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/indent.toml");
  const auto out = io::OutputDirectory::prepare(d.string(), true);
  EXPECT_TRUE(scene::run_forming_scene(s, scene::RunFiles(out)).ok());
  return d;
}

bool has_gnuplot() { return !reports::find_executable("gnuplot").empty(); }

TEST(RunReport, AnIndentRunGetsItsSummaryAndPlots) {
  const fs::path d = run_indent("done");
  ASSERT_TRUE(reports::is_fe_run_directory(d));
  const auto r = reports::render_run_report(d);
  const std::string md = io::read_text_file(r.markdown.string());
  EXPECT_NE(md.find("# spifit run report: indent (indent)"), std::string::npos) << md;
  EXPECT_NE(md.find("| increments / Newton iterations / cut-backs | 40 / "), std::string::npos) << md;
  EXPECT_NE(md.find("| status | ok |"), std::string::npos) << md;
  EXPECT_NE(md.find("where the time went"), std::string::npos) << md;
  // The scene's inputs as the run used them, and the energy account's error.
  EXPECT_NE(md.find("## Inputs"), std::string::npos) << md;
  EXPECT_NE(md.find("| contact.penalty | 1000 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| model.thickness | 0.3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| tool.radius | 5 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| energy balance error | "), std::string::npos) << md;
  EXPECT_NE(md.find(" of the external work) |"), std::string::npos) << md;
  EXPECT_TRUE(fs::exists(r.html));
  if (has_gnuplot()) {
    EXPECT_EQ(r.plots.size(), 3u);  // force, energies, iterations (no sections in the indent)
    const std::string gp = io::read_text_file((d / "plots" / "src" / "run_force.gp").string());
    EXPECT_NE(gp.find("set xlabel 'tool-tip depth [mm]'"), std::string::npos) << gp;
    EXPECT_NE(gp.find("set ylabel 'force [N]'"), std::string::npos) << gp;
    // The depth starts at the first increment's travel (0.05 mm) and ends at the path's 2 mm.
    const std::string dat = io::read_text_file((d / "plots" / "src" / "run_force.dat").string());
    EXPECT_NE(dat.find("\n0.0499999"), std::string::npos) << dat.substr(0, 200);
    EXPECT_NE(md.find("![Tool force](plots/run_force.svg)"), std::string::npos) << md;
    // Newton iterations are counts: whole-number tics; the legend (none here) never on the data.
    const std::string its = io::read_text_file((d / "plots" / "src" / "run_iterations.gp").string());
    EXPECT_NE(its.find("set ytics 1\nset format y '%.0f'"), std::string::npos) << its;
  }
  fs::remove_all(d);
}

// An explicit run reports its scheme, steps and kinetic energy instead of Newton counts.
TEST(RunReport, AnExplicitRunShowsItsStepsNotNewtonIterations) {
  const fs::path d = fs::temp_directory_path() / ("spifit_run_report_explicit_" + std::to_string(::getpid()));
  scene::FormingScene s = scene::read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/indent_explicit.toml");
  s.path.back().tip.z() = -0.5;
  const auto out = io::OutputDirectory::prepare(d.string(), true);
  ASSERT_TRUE(scene::run_forming_scene(s, scene::RunFiles(out)).ok());
  const auto r = reports::render_run_report(d);
  const std::string md = io::read_text_file(r.markdown.string());
  EXPECT_NE(md.find("| scheme | explicit, mst contact |"), std::string::npos) << md;
  EXPECT_NE(md.find("| output intervals / steps / cut steps | 10 / "), std::string::npos) << md;
  EXPECT_NE(md.find("| mass scaling / time scaling | 1e+06 / 1 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("Newton"), std::string::npos) << md;
  EXPECT_EQ(md.find("where the time went"), std::string::npos) << md;
  fs::remove_all(d);
}

TEST(RunReport, APartialDirectoryShowsWhatItHolds) {
  const fs::path d = run_indent("partial");
  auto summary = nlohmann::json::parse(io::read_text_file((d / "summary.json").string()));
  summary["status"] = "running";
  std::ofstream(d / "summary.json") << summary.dump(2);
  std::string force = io::read_text_file((d / "force.csv").string());
  force.resize(force.size() / 2);  // cut mid-row, as a killed run leaves it
  std::ofstream(d / "force.csv") << force;
  const auto r = reports::render_run_report(d, {false});
  const std::string md = io::read_text_file(r.markdown.string());
  EXPECT_NE(md.find("Status: running (or killed while running)"), std::string::npos) << md;
  fs::remove_all(d);
}

TEST(RunReport, ADirectoryThatIsNoFeRunIsNamed) {
  const fs::path d = fs::temp_directory_path() / ("spifit_run_report_none_" + std::to_string(::getpid()));
  fs::create_directories(d);
  std::ofstream(d / "summary.json") << R"({"kind": "tensile", "status": "ok"})";
  EXPECT_FALSE(reports::is_fe_run_directory(d));
  try {
    reports::render_run_report(d);
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not an output directory of `spifit run`"), std::string::npos) << e.what();
  }
  fs::remove_all(d);
}

}  // namespace
