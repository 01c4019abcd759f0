// Cone sections as fit experiments (docs/reference/file-formats.md "Fit file"): the section the small tiny
// cone takes after its last contour, read back as data (directly and through the laser-scan
// averaging of `spifit scan`), its residuals at the parameters that made it and away from them,
// and the input errors of the experiment; the part centre's depth as a scalar experiment.
#include "forward/io/input_error.hpp"
#include "forward/scenes/cone/cone_result.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "inverse/experiments/cone_section_experiment.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/experiments/scan_section.hpp"
#include "tests/support/input_errors.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

namespace fs = std::filesystem;
using namespace spifit;

namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

// The small tiny cone, two contours, at mu = 0.1 (clamp radius 13.5 mm).
fs::path tiny_cone() {
  const fs::path scene = test::write_tiny_cone(test::temp_path("cone.toml"), "", test::small_tiny_cone(2));
  std::ofstream(scene, std::ios::app) << "[contact]\nfriction = 0.1\n";
  return scene;
}

// z against r of the section after the last contour of a run of `scene`.
inverse::ForceCurve simulated_section(const fs::path& scene) {
  const auto sc = scene::read_scene(scene.string());
  const auto r = sc->run(scene::RunFiles(), {});
  EXPECT_TRUE(r->ok()) << r->message;
  const auto& cone = dynamic_cast<const scene::ConeResult&>(*r);
  EXPECT_EQ(cone.section_profiles.size(), 2u);
  return inverse::cone_section_curve(cone, 2, "r", "z");
}

fs::path write_fit(const fs::path& scene, const std::string& body) {
  const fs::path f = test::temp_path("fit.toml");
  std::ofstream(f) << "[fit]\ncard = \"" << src("materials/aa3003o_c3c4.toml")
                   << "\"\n[parameters.\"contact.friction\"]\ninitial = 0.14\nlower = 0.0\nupper = 0.5\n[[experiment]]\nscene = \""
                   << scene.string() << "\"\n" << body;
  return f;
}

// Residuals of the fit's only experiment at friction mu (the fit's card is the scene's).
std::vector<double> residuals_at(const inverse::FitProblem& problem, const fs::path& scene, double mu) {
  const auto& e = *problem.experiments.front();
  std::vector<double> r(static_cast<std::size_t>(e.num_residuals()), NAN);
  const inverse::ParameterPoint p{scene::read_scene(scene.string())->card()->params, {{"contact.friction", mu}}};
  EXPECT_TRUE(e.residuals(p, r.data()));
  return r;
}

double sum_of_squares(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return s;
}

double largest(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// The simulated section after the last contour, written as data, gives zero residuals at the
// friction that made it and nonzero ones at mu = 0.3 (noise 0.001 mm).
TEST(ConeSectionFit, ResidualsVanishAtTheTruthAndNotAtAnotherFriction) {
  const fs::path scene = tiny_cone();
  const inverse::ForceCurve c = simulated_section(scene);
  ASSERT_GE(c.x.size(), 5u);
  EXPECT_DOUBLE_EQ(c.x.front(), 0.0);
  EXPECT_NEAR(c.x.back(), 13.5, 1e-9);
  const fs::path data = test::temp_path("section.csv");
  {
    std::ofstream out(data);
    out << "r [mm],z [mm]\n";
    out.precision(17);
    // Midpoints between the nodes: the comparison interpolates.
    for (std::size_t i = 0; i + 1 < c.x.size(); ++i) out << 0.5 * (c.x[i] + c.x[i + 1]) << "," << 0.5 * (c.y[i] + c.y[i + 1]) << "\n";
  }
  const auto problem = inverse::read_fit_file(write_fit(scene, "section = \"last\"\ndata = \"" + data.string() + "\"\nnoise = 0.001\n").string());
  ASSERT_EQ(problem.experiments.front()->kind(), "cone_section");
  const double at_truth = largest(residuals_at(problem, scene, 0.1)), away = largest(residuals_at(problem, scene, 0.3));
  std::printf("largest residual at mu = 0.1: %.3g, at mu = 0.3: %.3g (noise 0.001 mm)\n", at_truth, away);
  EXPECT_LT(at_truth, 1e-9);
  EXPECT_GT(away, 1.0);
}

// z of the section c at r, linear between its nodes.
double section_z(const inverse::ForceCurve& c, double r) {
  const auto it = std::upper_bound(c.x.begin(), c.x.end(), r);
  const std::size_t i = std::clamp<std::size_t>(static_cast<std::size_t>(it - c.x.begin()), 1, c.x.size() - 1);
  return c.y[i - 1] + (c.y[i] - c.y[i - 1]) * (r - c.x[i - 1]) / (c.x[i] - c.x[i - 1]);
}

// The mean of z over [a, b] minus z at the middle: what a bin's mean (r, z) misses by the
// curvature of the section (uniform r in the bin).
double binning_error(const inverse::ForceCurve& c, double a, double b) {
  const int n = 2000;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) sum += section_z(c, a + (b - a) * (k + 0.5) / n);
  return sum / n - section_z(c, 0.5 * (a + b));
}

// A scan of the simulated section: 40 000 points uniform in r in [0, 13.5] mm and in the pie's
// polar angle, z = the section's z + N(0, 0.005 mm), averaged by `spifit scan` (0.5 mm bins in
// r). Its section.csv is the data as it is (x = r, y = z, noise_column = std): at the friction
// that made the section, each bin's z lies within its binning error and 4 standard errors of
// the simulated section; at mu = 0.3 the residuals are much larger.
TEST(ConeSectionFit, ASpifitScanSectionIsDataAsItIs) {
  const fs::path scene = tiny_cone();
  const inverse::ForceCurve c = simulated_section(scene);
  ASSERT_GE(c.x.size(), 5u);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> ur(0.0, 13.5), ut(0.0, 0.5 * std::numbers::pi);
  std::normal_distribution<double> noise(0.0, 0.005);
  std::vector<Eigen::Vector3d> cloud;
  for (int i = 0; i < 40000; ++i) {
    const double r = ur(rng), t = ut(rng);
    cloud.emplace_back(r * std::cos(t), r * std::sin(t), section_z(c, r) + noise(rng));
  }
  inverse::ScanSectionOptions o;
  o.bin = 0.5;
  const inverse::ScanSection s = inverse::average_scan_section(cloud, o);
  ASSERT_EQ(s.bins.size(), 27u);
  const fs::path dir = test::fresh_temp_path("scan");
  fs::create_directories(dir);
  std::ofstream(dir / "section.csv") << inverse::scan_section_csv(s, o);
  const auto problem = inverse::read_fit_file(
      write_fit(scene, "section = \"contour 2\"\ndata = \"" + (dir / "section.csv").string() + "\"\nx = \"r\"\ny = \"z\"\nnoise_column = \"std\"\n").string());
  const auto& e = *problem.experiments.front();
  ASSERT_EQ(e.num_residuals(), 27);
  const inverse::ParameterPoint truth{scene::read_scene(scene.string())->card()->params, {{"contact.friction", 0.1}}};
  const inverse::ExperimentCurve cmp = e.compare(truth);
  ASSERT_EQ(cmp.simulated.size(), 27u);
  double worst = 0.0;
  for (std::size_t i = 0; i < s.bins.size(); ++i) {
    const auto& b = s.bins[i];
    const double bound = std::abs(binning_error(c, b.lower, b.upper)) + 4.0 * b.spread_std / std::sqrt(double(b.points));
    EXPECT_NEAR(cmp.simulated[i], cmp.measured[i], bound) << "bin " << i << " [" << b.lower << ", " << b.upper << "] mm";
    worst = std::max(worst, std::abs(cmp.simulated[i] - cmp.measured[i]));
  }
  const std::vector<double> r1 = residuals_at(problem, scene, 0.1), r3 = residuals_at(problem, scene, 0.3);
  std::printf("scan vs section at mu = 0.1: largest |dz| %.3g mm, largest residual %.3g, sum of squares %.3g; at mu = 0.3: %.3g, %.3g\n",
              worst, largest(r1), sum_of_squares(r1), largest(r3), sum_of_squares(r3));
  EXPECT_GT(sum_of_squares(r3), 10.0 * sum_of_squares(r1));
}

// centre_depth: the last row of stages.csv as an observable of the cone (what `observable =
// "centre_depth"` of a fit compares), the depth of the axis point of the last section; zero
// residual at the run's own value.
TEST(ConeCentreDepth, IsTheLastStageRowAndAScalarOfAFit) {
  const fs::path scene = tiny_cone();
  const auto sc = scene::read_scene(scene.string());
  const auto r = sc->run(scene::RunFiles(), {});
  ASSERT_TRUE(r->ok()) << r->message;
  const auto& cone = dynamic_cast<const scene::ConeResult&>(*r);
  ASSERT_EQ(cone.stages.size(), 1u);
  const double depth = cone.stages.column("centre_depth").back();
  const scene::Observable* o = scene::find_scene_kind("cone")->find_observable("centre_depth");
  ASSERT_NE(o, nullptr);
  EXPECT_EQ(o->value(*r, {}), depth);
  // The stage ends at the end of the path, a few increments after contour 2 (its lift-off): the
  // axis node, the section's first point, has moved by less than 1e-6 mm since that section.
  const scene::SectionPoint& axis = cone.section_profiles.back().points.front();
  std::printf("centre depth after the stage: %.6g mm (axis point of the last section: r = %g, z = %.6g mm)\n", depth, axis.r, axis.z);
  EXPECT_EQ(axis.r, 0.0);
  EXPECT_NEAR(depth, -axis.z, 1e-6);
  EXPECT_GT(depth, 0.0);
  char value[64];
  std::snprintf(value, sizeof value, "%.17g", depth);
  const auto problem = inverse::read_fit_file(write_fit(scene, std::string("observable = \"centre_depth\"\nvalue = ") + value + "\nnoise = 0.001\n").string());
  EXPECT_EQ(residuals_at(problem, scene, 0.1), std::vector<double>{0.0});
}

std::string read_error(const fs::path& f) {
  return test::input_error_of([&] { inverse::read_fit_file(f.string()); });
}

// Each error names the file, the key and the value (a data file's errors: the data file and the
// column); the tiny cone takes 2 sections, from the axis to the clamp at r = 13.5 mm.
TEST(ConeSectionFitFile, InputErrorsNameFileKeyAndValue) {
  const fs::path scene = test::write_tiny_cone(test::temp_path("cone.toml"), "", test::small_tiny_cone(2));
  const fs::path data = test::write_temp_file("data.csv", "r [mm],z [mm],std [mm]\n1.0,-0.5,0.01\n2.0,-0.4,0.01\n");
  const fs::path wide = test::write_temp_file("wide.csv", "r [mm],z [mm]\n1.0,-0.5\n14.0,0.0\n");
  const fs::path flat = test::write_temp_file("flat.csv", "r [mm],z [mm],std [mm]\n1.0,-0.5,0.01\n2.0,-0.4,0.0\n");
  const fs::path line = test::write_tiny_line(test::temp_path("line.toml"));
  const std::string d = "data = \"" + data.string() + "\"\n";
  struct Case {
    fs::path scene;
    std::string body, file, message;
  };
  const std::string takes = "scene " + scene.stem().string() + " takes one after each of its 2 contours (\"last\" or \"contour K\", 1 <= K <= 2)";
  const std::vector<Case> cases{
      {scene, "section = \"contour 3\"\n" + d, "FIT", "experiment[0].section = \"contour 3\": no such section: " + takes},
      {scene, "section = \"stage 1\"\n" + d, "FIT", "experiment[0].section = \"stage 1\": not a section of a cone: " + takes},
      {scene, "section = \"last\"\nx = \"theta\"\n" + d, "FIT", "experiment[0].x = \"theta\": not an abscissa of a cone section (known: r, r0)"},
      {scene, "section = \"last\"\ny = \"depth\"\n" + d, "FIT", "experiment[0].y = \"depth\": not a column of a cone section (known: z, thickness)"},
      {scene, "section = \"last\"\ndata = \"" + wide.string() + "\"\n", wide.string(),
       "column r = 14: outside the simulated range [0, 13.5] mm (from the axis to the clamp)"},
      {scene, "section = \"last\"\nnoise_column = \"std\"\nnoise = 0.01\n" + d, "FIT",
       "experiment[0].noise = 0.01: noise_column gives each point's standard deviation; take one of them"},
      {scene, "section = \"last\"\nnoise_column = \"std\"\ndata = \"" + flat.string() + "\"\n", flat.string(),
       "column std = 0: standard deviations must be > 0 (row 2)"},
      {line, "section = \"E\"\nx = \"x\"\nnoise_column = \"std\"\n" + d, "FIT",
       "experiment[0].noise_column = \"std\": only for the sections of cone scenes (section = ...)"},
  };
  for (const auto& c : cases) {
    const fs::path f = write_fit(c.scene, c.body);
    const std::string file = c.file == "FIT" ? f.string() : c.file;
    EXPECT_EQ(read_error(f), file + ": " + c.message);
  }
}

}  // namespace
