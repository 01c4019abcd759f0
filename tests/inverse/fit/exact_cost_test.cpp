// Fits with exact FE Jacobians (inverse/fit/exact_cost.hpp, docs/design/sensitivities.md): the
// Jacobian of a force curve and of a section's z (a line's, a cone's) from one run with sensitivities, in the fit's
// internal coordinates (a log-scaled parameter, hill.G with H = 2 - G, the contact penalty),
// against central differences of whole runs; which scenes the fit file differentiates, and its
// errors.
#include "forward/io/input_error.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "inverse/experiments/synthetic.hpp"
#include "inverse/fit/exact_cost.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/fit_progress.hpp"
#include "inverse/fit/run_fit.hpp"
#include "tests/support/input_errors.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

namespace fs = std::filesystem;
using namespace spifit;

namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

// The tiny line test without friction, its Fz against travel and its section at C (synthetic,
// from card C.3 + C.4, with noise of 1 N and 0.01 mm: a fit's standard errors are then finite).
struct TinyData {
  fs::path scene, fz, section;
};
TinyData tiny_data() {
  TinyData d;
  d.scene = test::write_tiny_line(test::temp_path("line.toml"));
  const auto sc = scene::read_scene(d.scene.string());
  d.fz = test::temp_path("fz.csv");
  inverse::SyntheticOptions o;
  o.x = "travel";
  o.y = "fz";
  o.every = 4;
  o.noise = 1.0;
  std::ofstream(d.fz) << inverse::synthetic_force_curve_csv(*sc, o);
  d.section = test::temp_path("section_C.csv");
  inverse::SyntheticOptions s;
  s.x = "x";
  s.y = "z";
  s.noise = 0.01;
  std::ofstream(d.section) << inverse::synthetic_section_csv(*sc, "C", s);
  return d;
}

const char* kParameters =
    "[parameters.\"swift.K\"]\ninitial = 170.0\nlower = 100.0\nupper = 300.0\n"
    "[parameters.\"swift.n\"]\ninitial = 0.25\nlower = 0.05\nupper = 0.5\nlog = true\n"
    "[parameters.\"hill.G\"]\ninitial = 0.95\nlower = 0.6\nupper = 1.4\n"
    "[parameters.\"contact.penalty\"]\ninitial = 1000.0\nlower = 200.0\nupper = 5000.0\n";

std::string fit_text(const TinyData& d, const std::string& extra = "", const std::string& parameters = kParameters) {
  return "[fit]\ncard = \"" + src("materials/aa3003o_c3c4.toml") + "\"\nnormalise_hill = true\n" + extra + parameters +
         "[[experiment]]\nname = \"press\"\nscene = \"" + d.scene.string() + "\"\ndata = \"" + d.fz.string() +
         "\"\nx = \"travel\"\ny = \"fz\"\nnoise = 1.0\n"
         "[[experiment]]\nname = \"shape\"\nscene = \"" + d.scene.string() + "\"\nsection = \"C\"\ndata = \"" + d.section.string() +
         "\"\nnoise = 0.01\n";
}

fs::path write_fit(const std::string& text) {
  const fs::path f = test::temp_path("fit.toml");
  std::ofstream(f) << text;
  return f;
}

}  // namespace

// Scalar observables of the same run: the peak of Fz, and Fz's mean and ripple over the line.
std::string scalar_experiments(const TinyData& d) {
  std::string out;
  for (const char* body : {"name = \"peak\"\nobservable = \"peak_fz\"\nvalue = 500.0\nnoise = 5.0\n",
                           "name = \"mean\"\nobservable = \"mean_fz\"\nvalue = 400.0\nnoise = 5.0\nwindow = [6.0, 18.0]\n",
                           "name = \"ripple\"\nobservable = \"ripple_fz\"\nvalue = 0.1\nnoise = 0.01\nwindow = [6.0, 18.0]\n"})
    out += "[[experiment]]\nscene = \"" + d.scene.string() + "\"\n" + body;
  return out;
}

// Each column of the exact Jacobian (a force curve, a section's z, three scalar observables)
// against central differences of whole runs in the internal coordinate, with steps 4h, h and h/4 (h = 1e-4 of the value): it lies within the differences'
// own spread (their largest change from one step to the next), or within 1e-6 of the column's
// norm where they agree closer than that (an FE run's residuals wobble by about 1e-11 of
// themselves from its Newton tolerances: 1e-7 of a derivative at these steps).
static void expect_columns_within_central_differences(const inverse::FitProblem& problem) {
  const auto& ps = *problem.parameters;
  const int p = ps.num_free();
  for (const auto& e : problem.experiments) {
    SCOPED_TRACE(e->name());
    ASSERT_EQ(e->jacobian(), "exact");
    const int m = e->num_residuals();
    std::atomic<long> runs{0};
    inverse::ExactFeExperimentCost cost(&ps, e.get(), &runs);
    const std::vector<double> x = ps.initial_internal();
    std::vector<double> r(static_cast<std::size_t>(m)), jac(static_cast<std::size_t>(m * p));
    const double* xs[] = {x.data()};
    double* jacs[] = {jac.data()};
    ASSERT_TRUE(cost.Evaluate(xs, r.data(), jacs));
    std::vector<double> plain(r.size());
    ASSERT_TRUE(cost.Evaluate(xs, plain.data(), nullptr));
    EXPECT_EQ(plain, r);  // residuals alone: the same run's
    for (int k = 0; k < p; ++k) {
      auto central = [&](double h) {
        std::vector<double> xp = x, xm = x, rp(r.size()), rm(r.size()), c(r.size());
        xp[static_cast<std::size_t>(k)] += h;
        xm[static_cast<std::size_t>(k)] -= h;
        EXPECT_TRUE(e->residuals(ps.point(xp.data()), rp.data()));
        EXPECT_TRUE(e->residuals(ps.point(xm.data()), rm.data()));
        for (std::size_t i = 0; i < c.size(); ++i) c[i] = (rp[i] - rm[i]) / (2.0 * h);
        return c;
      };
      const double h = 1e-4 * std::max(std::abs(x[static_cast<std::size_t>(k)]), 1.0);
      const std::vector<double> c0 = central(4.0 * h), c1 = central(h), c4 = central(h / 4.0);
      double norm = 0.0, spread_large = 0.0, spread_small = 0.0, error = 0.0;
      for (int i = 0; i < m; ++i) {
        const auto u = static_cast<std::size_t>(i);
        norm += c4[u] * c4[u];
        spread_large += std::pow(c0[u] - c1[u], 2);
        spread_small += std::pow(c1[u] - c4[u], 2);
        error += std::pow(jac[u * static_cast<std::size_t>(p) + static_cast<std::size_t>(k)] - c4[u], 2);
      }
      norm = std::sqrt(norm), error = std::sqrt(error);
      const double spread = std::max(std::sqrt(spread_large), std::sqrt(spread_small));
      std::printf("%s column %s: |J| %.4g, exact - central(h/4) %.2e, central spread %.2e (relative)\n", e->name().c_str(),
                  ps.specs()[static_cast<std::size_t>(ps.free_indices()[static_cast<std::size_t>(k)])].name.c_str(), norm, error / norm,
                  spread / norm);
      EXPECT_GT(norm, 0.0);
      EXPECT_LE(error, std::max(spread, 1e-6 * norm)) << "column " << k;
    }
  }
}

TEST(ExactFeJacobian, ForceCurveAndSectionAgreeWithCentralDifferences) {
  const TinyData d = tiny_data();
  const auto problem = inverse::read_fit_file(write_fit(fit_text(d) + scalar_experiments(d)).string());
  ASSERT_EQ(problem.parameters->num_free(), 4);
  ASSERT_EQ(problem.experiments.size(), 5u);
  expect_columns_within_central_differences(problem);
}

// The columns of a fit to a section's thickness against x0, with data made from the scene itself
// (noise 0.001 mm), against central differences.
static void expect_thickness_columns(const fs::path& scene, const std::string& section, const std::string& card, const std::string& parameters,
                                     const std::string& name) {
  const auto sc = scene::read_scene(scene.string());
  const fs::path thickness = test::temp_path(name + ".csv");
  inverse::SyntheticOptions s;
  s.x = "x0";
  s.y = "thickness";
  s.noise = 0.001;
  std::ofstream(thickness) << inverse::synthetic_section_csv(*sc, section, s);
  const auto problem = inverse::read_fit_file(
      write_fit("[fit]\ncard = \"" + src("materials/" + card) + "\"\n" + parameters + "[[experiment]]\nname = \"" + name + "\"\nscene = \"" +
                scene.string() + "\"\nsection = \"" + section + "\"\nx = \"x0\"\ny = \"thickness\"\ndata = \"" + thickness.string() +
                "\"\nnoise = 0.001\n")
          .string());
  ASSERT_EQ(problem.experiments.size(), 1u);
  expect_columns_within_central_differences(problem);
  fs::remove(thickness);
}

// The section's thickness at C (the elements' committed thickness derivatives, averaged at the
// nodes as the thickness is), with respect to Swift's K and n.
TEST(ExactFeJacobian, SectionThicknessAgreesWithCentralDifferences) {
  expect_thickness_columns(tiny_data().scene, "C", "aa3003o_c3c4.toml",
                           "[parameters.\"swift.K\"]\ninitial = 170.0\nlower = 100.0\nupper = 300.0\n"
                           "[parameters.\"swift.n\"]\ninitial = 0.25\nlower = 0.05\nupper = 0.5\nlog = true\n",
                           "thinning");
}

// The friction column of a fit to a cone's section after its last contour (z against the moving
// r), with data made from the cone itself, against central differences.
static void expect_cone_section_column(const test::TinyCone& geometry, const std::string& extra, const std::string& name) {
  const fs::path scene = test::write_tiny_cone(test::temp_path(name + ".toml"), extra, geometry);
  const auto r = scene::read_scene(scene.string())->run(scene::RunFiles(), {});
  ASSERT_TRUE(r->ok()) << r->message;
  const scene::ResultCurve c = r->contour_section(2, "r", "z");
  ASSERT_GE(c.x.size(), 5u);
  const fs::path data = test::temp_path(name + "_section.csv");
  {
    std::ofstream out(data);
    out << "r [mm],z [mm]\n";
    out.precision(17);
    for (std::size_t i = 0; i + 1 < c.x.size(); ++i) out << 0.5 * (c.x[i] + c.x[i + 1]) << "," << 0.5 * (c.y[i] + c.y[i + 1]) + 0.002 << "\n";
  }
  const auto problem = inverse::read_fit_file(
      write_fit("[fit]\ncard = \"" + src("materials/aa3003o_c3c4.toml") + "\"\n" +
                "[parameters.\"contact.friction\"]\ninitial = 0.12\nlower = 0.0\nupper = 0.5\n"
                "[[experiment]]\nname = \"" + name + "\"\nscene = \"" + scene.string() + "\"\nsection = \"last\"\ndata = \"" + data.string() +
                "\"\nnoise = 0.001\n")
          .string());
  ASSERT_EQ(problem.experiments.size(), 1u);
  expect_columns_within_central_differences(problem);
  fs::remove(data);
  fs::remove(scene);
}

// A shell cone's section: the nodes' r and z derivatives through the pie's cyclic ties, virtual
// tools and friction, with respect to mu.
TEST(ExactFeJacobian, ConeSectionAgreesWithCentralDifferences) {
  expect_cone_section_column(test::small_tiny_cone(2), "[contact]\nfriction = 0.1\n", "cone_shape");
}

// The same cone in two layers of bricks: the section's z through the family's mid-surface (each
// node column's midpoint), the pie's ties on three-DOF nodes, and friction on the top faces.
// Converged to 1e-8 (tighter, the bricks' Newton stalls): at the scene's own tolerance the
// solver's error, not the derivative's, dominates the difference. Swift's K is not compared
// here: its central differences scatter by half the derivative at single increments of this
// coarse pie (docs/design/sensitivities.md, "Solids").
TEST(ExactFeJacobian, BrickConeSectionAgreesWithCentralDifferences) {
  test::TinyCone geometry = test::small_tiny_cone(2);
  geometry.element = "brick";
  geometry.layers = 2;
  expect_cone_section_column(geometry, "force_tolerance = 1e-8\ndisplacement_tolerance = 1e-8\n[contact]\nfriction = 0.1\n", "brick_cone_shape");
}

// The indent in three layers of bricks: its section's thickness against x0 (each node column's
// length), with respect to Swift's K (hill.G and the others through the forces:
// SensitivityCheck.BricksOnTheIndent), converged to 1e-10 (at the scene's tolerance the solver's
// error puts the central differences 1e-6 of the derivative off the exact solution's).
TEST(ExactFeJacobian, BrickSectionThicknessAgreesWithCentralDifferences) {
  std::string text = test::slurp(src("experiments/aa3003o/scenes/indent_brick.toml"));
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"../../../materials/", src("materials/")},
                                 std::pair<std::string, std::string>{"travel_per_increment = 0.05", "travel_per_increment = 0.1\nforce_tolerance = 1e-10\ndisplacement_tolerance = 1e-10"}}) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  const fs::path scene = test::temp_path("indent_brick.toml");
  std::ofstream(scene) << text;
  expect_thickness_columns(scene, "B", "aa3003o_c5_af_brick.toml", "[parameters.\"swift.K\"]\ninitial = 130.0\nlower = 100.0\nupper = 300.0\n",
                           "brick_thinning");
  fs::remove(scene);
}

// The same fit with the exact Jacobian and with central differences: the same card within a
// hundredth of its standard errors, the same standard errors within 0.1 %, from a third of the
// runs or fewer.
TEST(ExactFeJacobian, FitReachesTheCentralDifferenceCard) {
  const TinyData d = tiny_data();
  const char* two = "[parameters.\"swift.K\"]\ninitial = 200.0\nlower = 100.0\nupper = 400.0\n"
                    "[parameters.\"swift.n\"]\ninitial = 0.3\nlower = 0.05\nupper = 0.5\nlog = true\n";
  inverse::FitRunOptions options;
  options.threads = 2;
  long expected = -1;  // the runs the progress lines expect per iteration
  options.progress = std::make_shared<inverse::FitProgress>([&](const inverse::FitProgressEvent& e) { expected = e.runs_expected; });
  const auto exact = inverse::run_fit(inverse::read_fit_file(write_fit(fit_text(d, "", two)).string()), options);
  EXPECT_EQ(expected, 1);  // one run per point, not 1 + 2p
  options.progress = nullptr;
  const auto central = inverse::run_fit(inverse::read_fit_file(write_fit(fit_text(d, "jacobian = \"central\"\n", two)).string()), options);
  ASSERT_TRUE(exact.usable) << exact.termination;
  ASSERT_TRUE(central.usable) << central.termination;
  std::printf("exact: K %.6f n %.6f, %d iterations, %ld scene runs, %.1f s; central: K %.6f n %.6f, %d iterations, %ld scene runs, %.1f s\n",
              exact.values[0], exact.values[1], exact.iterations, exact.scene_runs, exact.wall_seconds, central.values[0], central.values[1],
              central.iterations, central.scene_runs, central.wall_seconds);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(exact.values[k], central.values[k], 1e-2 * central.uncertainty.std_error[k]) << k;
    EXPECT_NEAR(exact.uncertainty.std_error[k], central.uncertainty.std_error[k], 1e-3 * central.uncertainty.std_error[k]) << k;
  }
  EXPECT_LT(3 * exact.scene_runs, central.scene_runs);
}

// Which scene files the fit differentiates, and the errors of [fit] jacobian.
TEST(ExactFeJacobian, FitFileChoosesAndRefuses) {
  const TinyData d = tiny_data();
  // The tool's radius as a parameter: central differences, said in a note; "exact" is refused.
  const std::string radius = "[parameters.\"tool.radius\"]\ninitial = 5.0\nlower = 4.0\nupper = 6.0\n";
  const auto p = inverse::read_fit_file(write_fit(fit_text(d, "", radius)).string());
  for (const auto& e : p.experiments) EXPECT_EQ(e->jacobian(), "central");
  bool noted = false;
  for (const auto& n : p.notes) noted = noted || (n.find("central differences") != std::string::npos && n.find("tool.radius") != std::string::npos);
  EXPECT_TRUE(noted);
  const fs::path f = write_fit(fit_text(d, "jacobian = \"exact\"\n", radius));
  const std::string e = test::input_error_of([&] { inverse::read_fit_file(f.string()); });
  for (const char* part : {"jacobian = \"exact\"", "tool.radius", "no exact sensitivity"})
    EXPECT_NE(e.find(part), std::string::npos) << "missing \"" << part << "\" in: " << e;
  EXPECT_EQ(e.rfind(f.string(), 0), 0u) << e;
  const fs::path g = write_fit(fit_text(d, "jacobian = \"forward\"\n"));
  const std::string bad = test::input_error_of([&] { inverse::read_fit_file(g.string()); });
  EXPECT_NE(bad.find("jacobian = \"forward\""), std::string::npos) << bad;
  // The penetration has no exact derivatives: its scene file falls back, with the force curve and
  // the section's z on it.
  const auto t = inverse::read_fit_file(write_fit(fit_text(d) + "[[experiment]]\nname = \"sink\"\nscene = \"" + d.scene.string() +
                                                  "\"\nobservable = \"max_penetration\"\nvalue = 0.05\nnoise = 0.01\n")
                                            .string());
  ASSERT_EQ(t.experiments.size(), 3u);
  for (const auto& x : t.experiments) EXPECT_EQ(x->jacobian(), "central") << x->name();
}
