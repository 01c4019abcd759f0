// The report of a fit on an FE scene: the tiny line test (tests/support/tiny_scenes.hpp) with
// its drag force Fx against the tool travel and its section at E, both made at mu = 0.1 and
// fitted from mu = 0.12 in one iteration, written like `spifit fit --out DIR` does and
// rendered. The plots of both curves are listed with axis labels in words and units, the
// residual plots beside them; the forward runs per experiment and scene file and the shares of
// the Fisher information are in fit.json and the report, and they add up.
#include "tests/support/csv_rows.hpp"
#include "tests/support/markdown_rows.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/common/fe_scene_result.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "inverse/experiments/fe_experiment.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/fit_output.hpp"
#include "inverse/fit/run_fit.hpp"
#include "reports/fit_report.hpp"
#include "reports/plot.hpp"
#include "reports/report_format.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace fs = std::filesystem;
using nlohmann::json;
using namespace spifit;

namespace {

using test::md_row;
using test::md_section;
using test::slurp;

struct FeFit {
  fs::path dir;
  inverse::FitResult result;
};

// The fit, its outputs in DIR and the report (with plots when gnuplot is there).
FeFit run_fe_fit() {
  const fs::path scene = test::write_tiny_line(test::temp_path("line.toml"));
  std::ofstream(scene, std::ios::app) << "[contact]\nfriction = 0.1\n";
  // The measurements: every 4th point of the drag force and the section, from one run.
  const auto sc = scene::read_scene(scene.string());
  const auto run = sc->run(scene::RunFiles(), scene::RunControl());
  const auto& fe = dynamic_cast<const scene::FeSceneResult&>(*run);
  const auto fx = inverse::force_curve(fe.force, sc->tool_centre_path()->at_distance(0.0), sc->input("sheet.thickness"), sc->input("tool.radius"),
                                       "travel", "fx");
  const auto z = inverse::section_curve(*run, "E", "x", "z");
  const fs::path drag = test::temp_path("fx.csv"), shape = test::temp_path("section_E.csv");
  std::ofstream d(drag), e(shape);
  d << "travel [mm],fx [N]\n" << std::setprecision(17);
  for (std::size_t i = 4; i < fx.x.size(); i += 4) d << fx.x[i] << "," << fx.y[i] << "\n";
  e << "x [mm],z [mm]\n" << std::setprecision(17);
  for (std::size_t i = 0; i < z.x.size(); ++i) e << z.x[i] << "," << z.y[i] << "\n";
  d.close();
  e.close();
  const fs::path fit = test::write_temp_file(
      "fit.toml", "[fit]\ncard = \"" + std::string(SPIFIT_SOURCE_DIR) + "/materials/aa3003o_c3c4.toml\"\nmax_iterations = 1\n" +
                      "[parameters.\"contact.friction\"]\ninitial = 0.12\nlower = 0.0\nupper = 0.5\n" + "[[experiment]]\nname = \"drag\"\nscene = \"" +
                      scene.string() + "\"\ndata = \"" + drag.string() + "\"\nx = \"travel\"\ny = \"fx\"\nnoise = 1.0\n" +
                      "[[experiment]]\nname = \"shape\"\nscene = \"" + scene.string() + "\"\nsection = \"E\"\ndata = \"" + shape.string() +
                      "\"\nnoise = 0.01\n");
  const auto problem = inverse::read_fit_file(fit.string());
  FeFit f;
  f.dir = test::fresh_temp_path("out");
  f.result = inverse::run_fit(problem, {"", 2});
  std::printf("mu %.6f, %d iterations, %ld scene runs, %.1f s\n", f.result.values.at(0), f.result.iterations, f.result.scene_runs,
              f.result.wall_seconds);
  inverse::write_fit_outputs(problem, f.result, io::OutputDirectory::prepare(f.dir.string(), false));
  reports::render_fit_report(f.dir, {});
  return f;
}

// The forward runs: fit.json as the result counts them, the report as fit.json.
void expect_runs(const FeFit& f, const json& j, const std::string& md) {
  const auto& r = f.result;
  ASSERT_EQ(j["experiments"].size(), 2u);
  ASSERT_EQ(r.experiment_runs.size(), 2u);
  long evaluations = 0, scene_runs = 0;
  double seconds = 0.0;
  const std::string runs = md_section(md, "## Forward runs");
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& e = j["experiments"][i];
    const std::string name = e["name"];
    EXPECT_EQ(e["evaluations"].get<long>(), r.experiment_runs[i].evaluations) << name;
    EXPECT_EQ(e["scene_runs"].get<long>(), r.experiment_runs[i].scene_runs) << name;
    EXPECT_EQ(e["run_seconds"].get<double>(), r.experiment_runs[i].run_seconds) << name;
    evaluations += e["evaluations"].get<long>();
    scene_runs += e["scene_runs"].get<long>();
    seconds += e["run_seconds"].get<double>();
    EXPECT_EQ(e["jacobian"], "exact") << name;  // friction and the card's parameters: exact derivatives
    EXPECT_EQ(md_row(runs, name), (std::vector<std::string>{name, e["kind"], std::to_string(e["evaluations"].get<long>()),
                                                             "exact (FE run)", std::to_string(e["scene_runs"].get<long>()),
                                                             reports::format_significant(e["run_seconds"].get<double>(), 3)}))
        << runs;
  }
  // The drag curve is evaluated first at the start: the first run is its own; the section reads it.
  EXPECT_GE(j["experiments"][0]["scene_runs"].get<long>(), 1);
  // One more evaluation per experiment than forward_runs counts: the check at the start.
  EXPECT_EQ(evaluations, j["forward_runs"].get<long>() + 2);
  // Every run counts for one experiment; one scene file, no failures.
  EXPECT_EQ(scene_runs, j["scene_runs"].get<long>());
  ASSERT_EQ(j["runs_by_scene"].size(), 1u);
  const auto& file = j["runs_by_scene"][0];
  const std::string scene = file["scene"];
  EXPECT_EQ(scene, test::temp_path("line.toml").string());
  EXPECT_EQ(file["runs"].get<long>(), scene_runs);
  EXPECT_EQ(file["failures"].get<long>(), 0);
  EXPECT_EQ(file["retried"].get<long>(), 0);
  EXPECT_NEAR(file["seconds"].get<double>(), seconds, 1e-9 * seconds);
  EXPECT_GT(file["median_seconds"].get<double>(), 0.0);
  EXPECT_LE(file["median_seconds"].get<double>(), file["seconds"].get<double>());
  EXPECT_EQ(md_row(runs, scene), (std::vector<std::string>{scene, std::to_string(scene_runs), "0", "0", reports::format_significant(file["seconds"].get<double>(), 3),
                                                           reports::format_significant(file["median_seconds"].get<double>(), 3)}))
      << runs;
}

// The drag force informs the friction (Fx moves by about Fz times the change of mu, against a
// noise of 1 N); the section at E hardly (it moves by hundredths of a mm, against 0.01 mm): about
// 0.02 % of the information. The shares add up to 1.
void expect_information(const json& j, const std::string& md) {
  const std::string info = md_section(md, "### Which experiment informs which parameter");
  const double drag = j["experiments"][0]["information_share"]["contact.friction"].get<double>();
  const double shape = j["experiments"][1]["information_share"]["contact.friction"].get<double>();
  EXPECT_GT(drag, 0.99);
  EXPECT_GT(shape, 0.0);
  EXPECT_LT(shape, 0.01);
  EXPECT_NEAR(drag + shape, 1.0, 1e-12);
  EXPECT_EQ(md_row(info, "drag"), (std::vector<std::string>{"drag", reports::format_percent(drag)})) << info;
  EXPECT_EQ(md_row(info, "shape"), (std::vector<std::string>{"shape", reports::format_percent(shape)})) << info;
}

TEST(FeFitReport, CurvesSectionsRunsAndInformation) {
  const FeFit f = run_fe_fit();
  ASSERT_TRUE(f.result.usable) << f.result.termination;
  const std::string md = slurp(f.dir / "report.md");
  const json j = json::parse(slurp(f.dir / "fit.json"));
  expect_runs(f, j, md);
  expect_information(j, md);
  // The simulated curves at the start and at the solution are in the data files.
  for (const char* name : {"drag", "shape"}) {
    std::ifstream csv(f.dir / "experiments" / (std::string(name) + ".csv"));
    std::string header;
    std::getline(csv, header);
    EXPECT_EQ(header, std::string(name) == "drag" ? "travel,measured,simulated_initial,simulated_final" : "x,measured,simulated_initial,simulated_final");
  }
  if (reports::find_executable("gnuplot").empty()) GTEST_SKIP() << "gnuplot is not on PATH: no plots to check";
  struct Plot {
    std::string stem, caption, xlabel, ylabel;
  };
  const std::vector<Plot> plots{
      {"01_drag_fit", "drag: measured points, initial (dashed) and fitted simulation", "tool travel [mm]", "Fx [N]"},
      {"01_drag_residuals", "drag: residuals (fitted - measured) / divisor; dashed lines at ±1 σ", "tool travel [mm]", "(fitted - measured) / noise σ"},
      {"02_shape_fit", "shape: measured points, initial (dashed) and fitted simulation", "x [mm]", "z [mm]"},
      {"02_shape_residuals", "shape: residuals (fitted - measured) / divisor; dashed lines at ±1 σ", "x [mm]", "(fitted - measured) / noise σ"},
  };
  const std::string curves = md_section(md, "## Curves: data and fit");
  for (const auto& p : plots) {
    EXPECT_NE(curves.find("![" + p.caption + "](plots/" + p.stem + ".svg)"), std::string::npos) << p.stem << " not listed in:\n" << curves;
    const std::string gp = slurp(f.dir / "plots" / "src" / (p.stem + ".gp")), svg = slurp(f.dir / "plots" / (p.stem + ".svg"));
    EXPECT_NE(gp.find("set xlabel '" + p.xlabel + "'\n"), std::string::npos) << gp;
    EXPECT_NE(gp.find("set ylabel '" + p.ylabel + "'\n"), std::string::npos) << gp;
    EXPECT_NE(svg.find(p.xlabel), std::string::npos) << p.stem;
    EXPECT_NE(svg.find(p.ylabel), std::string::npos) << p.stem;
  }
  // The data plots show three series (measured, initial, fitted); the residual plots keep the
  // lines at +-1 sigma in view; the section's legend sits beside the shape.
  for (const char* stem : {"01_drag_fit", "02_shape_fit"}) {
    const std::string gp = slurp(f.dir / "plots" / "src" / (std::string(stem) + ".gp"));
    for (const char* title : {"title 'measured'", "title 'initial simulation", "title 'fitted simulation'"})
      EXPECT_NE(gp.find(title), std::string::npos) << stem << ": " << title;
  }
  const std::string residuals = slurp(f.dir / "plots" / "src" / "01_drag_residuals.gp");
  double lo = 0.0, hi = 0.0, largest = 0.0;
  ASSERT_NE(residuals.find("set yrange ["), std::string::npos) << residuals;
  ASSERT_EQ(std::sscanf(residuals.c_str() + residuals.find("set yrange [") + 12, "%lf:%lf", &lo, &hi), 2);
  for (const auto& row : test::read_csv_rows(f.dir / "experiments" / "drag.csv")) largest = std::max(largest, std::abs(row[3] - row[1]));  // noise 1 N
  EXPECT_DOUBLE_EQ(hi, std::max(1.2, 1.15 * largest));
  EXPECT_DOUBLE_EQ(lo, -hi);
  // Every legend beside the plot, off the data.
  EXPECT_NE(slurp(f.dir / "plots" / "src" / "02_shape_fit.gp").find("set key outside right top"), std::string::npos);
  EXPECT_NE(slurp(f.dir / "plots" / "src" / "01_drag_fit.gp").find("set key outside right top"), std::string::npos);
  fs::remove_all(f.dir);
}

}  // namespace
