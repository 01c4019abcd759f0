// Fits on FE scenes (docs/design/identification.md, "Fits on FE scenes"): the force curve of a run,
// the fit file's FE experiments and their input errors, the shared runs and their failures, and
// a twin experiment that recovers the friction coefficient of the tiny line test.
#include "forward/io/input_error.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "inverse/runs/fe_evaluation_job.hpp"
#include "inverse/experiments/fe_experiment.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/numeric_cost.hpp"
#include "inverse/fit/run_fit.hpp"
#include "inverse/experiments/synthetic.hpp"
#include "tests/support/input_errors.hpp"
#include "tests/support/temp_files.hpp"
#include "tests/support/tiny_scenes.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace spifit;

namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

// A tool going down from z_c = t/2 + R (tip on the top surface) in 0.5 mm steps, then back up.
scene::ToolForceHistory descent(double t, double r) {
  scene::ToolForceHistory h;
  const double z0 = 0.5 * t + r;
  for (int k = 1; k <= 6; ++k) {
    scene::ToolForceSample s;
    const double depth = k <= 4 ? 0.5 * k : 0.5 * (8 - k);  // 0.5, 1, 1.5, 2, then 1.5, 1
    s.travel = 0.5 * k;
    s.time = 0.05 * k;
    s.centre = Eigen::Vector3d(3.0, 4.0, z0 - depth);
    s.force = Eigen::Vector3d(10.0 * k, 0.0, 100.0 * depth);
    h.add(s);
  }
  return h;
}

TEST(ForceCurve, DepthStartsAtTheTopSurfaceAndEndsWhereTheToolTurns) {
  const double t = 1.2, r = 5.0;
  const auto h = descent(t, r);
  const Eigen::Vector3d start(3.0, 4.0, 0.5 * t + r);
  const auto c = inverse::force_curve(h, start, t, r, "depth", "fz");
  ASSERT_EQ(c.x.size(), 5u);  // the start and the four samples going down
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    EXPECT_NEAR(c.x[i], 0.5 * static_cast<double>(i), 1e-12);
    EXPECT_NEAR(c.y[i], 50.0 * static_cast<double>(i), 1e-9);
  }
  const auto tr = inverse::force_curve(h, start, t, r, "travel", "fx");
  EXPECT_EQ(tr.x.size(), 7u);  // travel keeps increasing
  // Polar components at the centre's angle atan2(4, 3): Fr = 0.6 Fx, Ftheta = -0.8 Fx.
  const auto fr = inverse::force_curve(h, start, t, r, "travel", "fr");
  const auto ft = inverse::force_curve(h, start, t, r, "travel", "ftheta");
  EXPECT_NEAR(fr.y[2], 0.6 * 20.0, 1e-12);
  EXPECT_NEAR(ft.y[2], -0.8 * 20.0, 1e-12);
  EXPECT_THROW(inverse::force_curve(h, start, t, r, "angle", "fz"), std::invalid_argument);
}

// The tiny line test (tests/support/tiny_scenes.hpp) at mu = 0.1 and its drag force Fx along
// the travel, written as a synthetic measurement without noise.
struct TinyLineData {
  fs::path scene, data;
};
TinyLineData tiny_line_data(const std::string& y = "fx") {
  TinyLineData d;
  d.scene = test::write_tiny_line(test::temp_path("line.toml"));
  std::ofstream(d.scene, std::ios::app) << "[contact]\nfriction = 0.1\n";
  d.data = test::temp_path(y + ".csv");
  inverse::SyntheticOptions o;
  o.x = "travel";
  o.y = y;
  o.every = 4;
  std::ofstream(d.data) << inverse::synthetic_force_curve_csv(*scene::read_scene(d.scene.string()), o);
  return d;
}

std::string fit_head(const std::string& parameters) {
  return "[fit]\ncard = \"" + src("materials/aa3003o_c3c4.toml") + "\"\n" + parameters;
}
std::string experiment(const fs::path& scene, const std::string& body) { return "[[experiment]]\nscene = \"" + scene.string() + "\"\n" + body; }
const char* kFriction = "[parameters.\"contact.friction\"]\ninitial = 0.14\nlower = 0.0\nupper = 0.5\n";

fs::path write_fit(const std::string& text) {
  const fs::path f = test::temp_path("fit.toml");
  std::ofstream(f) << text;
  return f;
}

std::string read_error(const fs::path& f) {
  return test::input_error_of([&] { inverse::read_fit_file(f.string()); });
}

TEST(FeFitFile, InputErrorsNameFileKeyAndValue) {
  const fs::path scene = test::write_tiny_line(test::temp_path("line.toml"));
  const fs::path data = test::temp_path("fz.csv");
  std::ofstream(data) << "depth [mm],fz [N]\n1.0,10.0\n2.0,20.0\n";
  const fs::path deep = test::temp_path("deep.csv");
  std::ofstream(deep) << "depth [mm],fz [N]\n1.0,10.0\n3.5,20.0\n";  // the tool goes down 3 mm before it turns along x
  const std::string curve = "data = \"" + data.string() + "\"\n";
  struct Case {
    std::string fit;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases{
      {fit_head(kFriction) + experiment(scene, "observable = \"peak_fq\"\nvalue = 1.0\n"), {"observable = \"peak_fq\"", "not an observable of scene kind line", "peak_fz"}},
      {fit_head(kFriction) + experiment(scene, curve + "y = \"fq\"\n"), {"y = \"fq\"", "not a tool-force component", "ftheta"}},
      {fit_head(kFriction) + experiment(scene, curve + "x = \"angle\"\n"), {"x = \"angle\"", "depth, travel, time"}},
      {fit_head(kFriction) + experiment(scene, "data = \"" + deep.string() + "\"\n"), {"column depth", "3.5", "outside the simulated range [0, 3]"}},
      {fit_head("[parameters.\"contact.stickiness\"]\nlower = 0.0\nupper = 1.0\n") + experiment(scene, curve),
       {"parameters.contact.stickiness", "unknown parameter", "contact.friction"}},
      {fit_head("[parameters.\"contact.friction\"]\nlower = 0.0\nupper = 3.0\n") + experiment(scene, curve), {"parameters.contact.friction.upper = 3"}},
      {fit_head(kFriction) + experiment(scene, "observable = \"mean_fx\"\nvalue = 1.0\nwindow = [0.0, 90.0]\n"), {"window", "inside the tool path's travel"}},
      {fit_head(kFriction) + experiment(scene, "observable = \"increments\"\nvalue = 100.0\n"), {"observable = \"increments\"", "a count of the run"}},
      {fit_head(kFriction) + experiment(scene, curve + "value = 3.0\n"), {"value", "takes no scalar keys"}},
      {fit_head(kFriction) + experiment(scene, "contour_means = \"ftheta\"\n" + curve), {"contour_means", "only for scenes with contours"}},
      {fit_head(kFriction) + experiment(scene, "section = \"Q\"\n" + curve), {"section = \"Q\"", "no section at this path point", "C, E"}},
      {fit_head(kFriction) + experiment(scene, "section = \"E\"\ny = \"width\"\n" + curve), {"y = \"width\"", "z, thickness"}},
      {fit_head("[parameters.\"swift.K\"]\nlower = 50.0\nupper = 500.0\n[parameters.\"contact.friction\"]\nlower = 0.0\nupper = 0.5\n") +
           experiment(src("experiments/aa3003o/scenes/tensile_00.toml"), "data = \"" + src("experiments/aa3003o/data/tensile_00_c2_synthetic.csv") + "\"\n"),
       {"parameters.contact.friction", "unknown parameter", "with an FE scene"}},
  };
  for (const auto& c : cases) {
    const fs::path f = write_fit(c.fit);
    const std::string e = read_error(f);
    // The data file's errors name the data file, the others the fit file.
    EXPECT_TRUE(e.rfind(f.string(), 0) == 0 || e.rfind(deep.string(), 0) == 0) << e;
    for (const auto& part : c.parts) EXPECT_NE(e.find(part), std::string::npos) << "missing \"" << part << "\" in: " << e;
  }
}

// A contour range beyond a cone's path is an input error when the fit file is read (before any
// run): a scalar's `contours` and the contour column of `contour_means` data, naming the fit
// file, the key and its value. The small tiny cone of three contours.
TEST(FeFitFile, ContourRangeBeyondTheConeIsAnInputError) {
  const fs::path scene = test::write_tiny_cone(test::temp_path("cone.toml"), "", test::small_tiny_cone(3));
  EXPECT_EQ(scene::read_scene(scene.string())->contours(), 3);
  EXPECT_EQ(scene::read_scene(test::write_tiny_line(test::temp_path("line.toml")).string())->contours(), 0);
  const fs::path means = test::temp_path("means.csv"), beyond = test::temp_path("beyond.csv");
  std::ofstream(means) << "contour,ftheta_over_fz\n1,-0.2\n2,-0.21\n3,-0.22\n";
  std::ofstream(beyond) << "contour,ftheta_over_fz\n2,-0.21\n3,-0.22\n4,-0.23\n";
  const std::string steady = "observable = \"steady_ftheta_over_fz\"\nvalue = -0.2\n";
  const std::string beyond_path = "it has 3 contours (numbers 1 to 3)";
  struct Case {
    std::string body, key_value, message;
  };
  const std::vector<Case> errors{
      {steady + "contours = [2, 4]\n", ".contours = [2, 4]: ", "beyond the path of scene " + scene.string() + ": " + beyond_path},
      {steady + "contours = [4, 4]\n", ".contours = [4, 4]: ", "beyond the path of scene " + scene.string() + ": " + beyond_path},
      {"contour_means = \"ftheta_over_fz\"\ndata = \"" + beyond.string() + "\"\n", ".data = \"" + beyond.string() + "\": ",
       "column contour holds contour 4, beyond the path of scene " + scene.string() + ": " + beyond_path},
  };
  for (const auto& c : errors) {
    const fs::path f = write_fit(fit_head(kFriction) + experiment(scene, c.body));
    const std::string e = read_error(f);
    EXPECT_EQ(e.rfind(f.string() + ": ", 0), 0u) << e;
    EXPECT_NE(e.find(c.key_value + c.message), std::string::npos) << e;
  }
  // The whole path is fine.
  for (const std::string& body : {steady + "contours = [1, 3]\n", "contour_means = \"ftheta_over_fz\"\ndata = \"" + means.string() + "\"\n"}) {
    const fs::path f = write_fit(fit_head(kFriction) + experiment(scene, body));
    EXPECT_EQ(read_error(f), "(no error)") << body;
  }
}

// The shared runs: a point whose scene input the scene refuses is a failed run, listed with the
// reason; nothing runs.
TEST(SceneRuns, AnInputTheSceneRefusesIsAListedFailure) {
  const fs::path scene_file = test::write_tiny_line(test::temp_path("line.toml"));
  const auto sc = scene::read_scene(scene_file.string());
  inverse::SceneRuns runs(sc->card()->params);
  inverse::ParameterPoint p{sc->card()->params, {{"contact.friction", 5.0}}};
  EXPECT_EQ(runs.result(*sc, p), nullptr);
  const auto failures = runs.failures();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(runs.runs(), 0);
  const auto& f = failures.front();
  EXPECT_EQ(f.scene, scene_file.string());
  EXPECT_EQ(f.point, "contact.friction=5");
  EXPECT_NE(f.message.find("contact.friction = 5"), std::string::npos) << f.message;
  EXPECT_FALSE(f.recovered);
}

// A run past the fit's time limit (run_time_limit) is a listed failure and is not retried.
TEST(SceneRuns, ARunPastItsTimeLimitIsAListedFailure) {
  const fs::path scene_file = test::write_tiny_line(test::temp_path("line.toml"));
  const auto sc = scene::read_scene(scene_file.string());
  inverse::SceneRuns runs(sc->card()->params, 0.05);  // the run takes about a second
  EXPECT_EQ(runs.result(*sc, inverse::ParameterPoint{sc->card()->params, {}}, "press"), nullptr);
  EXPECT_EQ(runs.runs(), 1);
  const auto failures = runs.failures();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_NE(failures.front().message.find("time limit of 0.05 s passed at tool travel"), std::string::npos) << failures.front().message;
  EXPECT_FALSE(failures.front().recovered);
  // The run is logged for the experiment that asked, with its wall time (at least the limit).
  const auto log = runs.run_log();
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0].scene, scene_file.string());
  EXPECT_EQ(log[0].experiment, "press");
  EXPECT_FALSE(log[0].retry);
  EXPECT_FALSE(log[0].ok);
  EXPECT_GE(log[0].seconds, 0.05);
  EXPECT_LT(log[0].seconds, 30.0);
}

// Per scene file: runs (retries included), failed points (not the recovered ones; a point whose
// inputs the scene refused has no run), retries, total and median wall time of one run.
TEST(SceneRuns, RunsBySceneFile) {
  using Run = inverse::SceneRuns::Run;
  const std::vector<Run> log{{"a.toml", "e1", 3.0, false, false}, {"b.toml", "e2", 1.5, false, true}, {"a.toml", "e1", 1.0, true, true},
                             {"a.toml", "e2", 2.0, false, false}, {"a.toml", "e2", 6.0, true, false}};
  const std::vector<inverse::SceneRuns::Failure> failures{
      {"a.toml", "swift.K=150", "retried ...", true}, {"a.toml", "swift.K=160", "failed twice", false}, {"c.toml", "contact.friction=5", "refused", false}};
  const auto files = inverse::scene_file_runs(log, failures);
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].scene, "a.toml");
  EXPECT_EQ(files[0].runs, 4);
  EXPECT_EQ(files[0].failures, 1);
  EXPECT_EQ(files[0].retried, 2);
  EXPECT_EQ(files[0].seconds, 12.0);
  EXPECT_EQ(files[0].median_seconds, 2.5);  // of 1, 2, 3, 6
  EXPECT_EQ(files[1].scene, "b.toml");
  EXPECT_EQ(files[1].runs, 1);
  EXPECT_EQ(files[1].failures, 0);
  EXPECT_EQ(files[1].median_seconds, 1.5);
  EXPECT_EQ(files[2].scene, "c.toml");
  EXPECT_EQ(files[2].runs, 0);
  EXPECT_EQ(files[2].failures, 1);
  EXPECT_EQ(files[2].seconds, 0.0);
  EXPECT_TRUE(std::isnan(files[2].median_seconds));
}

// Twin experiment: the drag force Fx of the tiny line test made at mu = 0.1 (no noise) gives back
// mu = 0.1 from a start 40 % off; an Fz curve on the same scene shares every run.
TEST(FeFit, TinyLineFrictionIsRecoveredAndExperimentsShareTheirRuns) {
  const TinyLineData fx = tiny_line_data("fx");
  const fs::path fz = test::temp_path("fz.csv");
  {
    inverse::SyntheticOptions o;
    o.x = "travel";
    o.y = "fz";
    o.every = 4;
    std::ofstream(fz) << inverse::synthetic_force_curve_csv(*scene::read_scene(fx.scene.string()), o);
  }
  const fs::path f = write_fit(fit_head(kFriction) + experiment(fx.scene, "name = \"drag\"\ndata = \"" + fx.data.string() + "\"\nx = \"travel\"\ny = \"fx\"\nnoise = 1.0\n") +
                               experiment(fx.scene, "name = \"press\"\ndata = \"" + fz.string() + "\"\nx = \"travel\"\ny = \"fz\"\nnoise = 1.0\n"));
  const auto problem = inverse::read_fit_file(f.string());
  ASSERT_TRUE(problem.scene_runs);
  EXPECT_TRUE(problem.parameters->has_scene_inputs());
  inverse::FitRunOptions options;
  options.threads = 2;
  const auto r = inverse::run_fit(problem, options);
  std::printf("mu %.6f (start 0.14), %d iterations, %ld scene runs, %ld experiment evaluations, %.1f s, cost %.3g -> %.3g\n", r.values[0],
              r.iterations, r.scene_runs, r.forward_runs, r.wall_seconds, r.cost_initial, r.cost_final);
  ASSERT_TRUE(r.usable) << r.termination;
  EXPECT_NEAR(r.values[0], 0.1, 1e-4);
  ASSERT_EQ(r.uncertainty.ci95_lower.size(), 1u);
  EXPECT_LE(r.uncertainty.ci95_lower[0], 0.1 + 1e-4);
  EXPECT_GE(r.uncertainty.ci95_upper[0], 0.1 - 1e-4);
  // Two experiments read each run: at most half as many scene runs as experiment evaluations.
  EXPECT_LE(2 * r.scene_runs, r.forward_runs);
  EXPECT_TRUE(r.failed_runs.empty());
}


// The central-difference Jacobian of an FE experiment (the fit's own, numeric_cost.hpp: relative
// step 1e-6) against a reference with 100 times the step: the columns agree to 1e-4 of their
// norm (docs/design/identification.md, "Derivatives": the forward model's noise lies far below).
TEST(FeFit, JacobianOfAForceCurveAgreesWithALargerStep) {
  const TinyLineData fx = tiny_line_data("fx");
  const fs::path f = write_fit(fit_head(std::string(kFriction) + "[parameters.\"swift.K\"]\ninitial = 150.0\nlower = 100.0\nupper = 300.0\n") +
                               experiment(fx.scene, "data = \"" + fx.data.string() + "\"\nx = \"travel\"\ny = \"fx\"\nnoise = 1.0\n"));
  const auto problem = inverse::read_fit_file(f.string());
  const auto& ps = *problem.parameters;
  const inverse::Experiment& e = *problem.experiments.front();
  const int m = e.num_residuals(), p = ps.num_free();
  std::atomic<long> runs{0};
  inverse::NumericDiffExperimentCost cost(&ps, &e, &runs);
  const std::vector<double> x = ps.initial_internal();
  std::vector<double> r(static_cast<std::size_t>(m)), jac(static_cast<std::size_t>(m * p));
  const double* xs[] = {x.data()};
  double* jacs[] = {jac.data()};
  ASSERT_TRUE(cost.Evaluate(xs, r.data(), jacs));
  for (int k = 0; k < p; ++k) {
    const double h = 1e-4 * std::abs(x[static_cast<std::size_t>(k)]);
    std::vector<double> xp = x, xm = x, rp(r.size()), rm(r.size());
    xp[static_cast<std::size_t>(k)] += h;
    xm[static_cast<std::size_t>(k)] -= h;
    ASSERT_TRUE(e.residuals(ps.point(xp.data()), rp.data()));
    ASSERT_TRUE(e.residuals(ps.point(xm.data()), rm.data()));
    double diff = 0.0, norm = 0.0;
    for (int i = 0; i < m; ++i) {
      const double ref = (rp[static_cast<std::size_t>(i)] - rm[static_cast<std::size_t>(i)]) / (2.0 * h);
      diff += std::pow(jac[static_cast<std::size_t>(i * p + k)] - ref, 2);
      norm += ref * ref;
    }
    std::printf("column %d: |J| %.4g, relative difference %.2e\n", k, std::sqrt(norm), std::sqrt(diff / norm));
    EXPECT_GT(norm, 0.0);
    EXPECT_LT(std::sqrt(diff / norm), 1e-4) << "column " << k;
  }
}

// Twin experiment on a shape: the section at E of the tiny line test made at mu = 0.1 (no noise)
// gives back mu from 0.14. Friction drags the sheet: the section moves by up to 0.045 mm between
// mu = 0 and 0.2 on this coarse mesh (docs/design/identification.md, "What each observable identifies").
TEST(FeFit, TinyLineFrictionFromTheSectionAtE) {
  const fs::path scene = test::write_tiny_line(test::temp_path("line.toml"));
  std::ofstream(scene, std::ios::app) << "[contact]\nfriction = 0.1\n";
  const fs::path data = test::temp_path("section_E.csv");
  inverse::SyntheticOptions o;
  o.x = "x";
  o.y = "z";
  std::ofstream(data) << inverse::synthetic_section_csv(*scene::read_scene(scene.string()), "E", o);
  const fs::path f = write_fit(fit_head(kFriction) + experiment(scene, "section = \"E\"\ndata = \"" + data.string() + "\"\nnoise = 0.01\n"));
  const auto problem = inverse::read_fit_file(f.string());
  inverse::FitRunOptions options;
  options.threads = 2;
  const auto r = inverse::run_fit(problem, options);
  std::printf("mu %.6f from the section (start 0.14), %d iterations, %ld scene runs, %.1f s\n", r.values[0], r.iterations, r.scene_runs, r.wall_seconds);
  ASSERT_TRUE(r.usable) << r.termination;
  EXPECT_NEAR(r.values[0], 0.1, 1e-3);
}

// Fails chosen evaluations of an FE experiment, as a forward run that does not converge would:
// the first trial step of the optimiser and one perturbed run of its first Jacobian.
class FailingEvaluations final : public inverse::Experiment {
 public:
  explicit FailingEvaluations(std::shared_ptr<inverse::Experiment> inner) : inner_(std::move(inner)) {
    name_ = inner_->name();
    kind_ = inner_->kind();
  }
  int num_residuals() const override { return inner_->num_residuals(); }
  bool residuals(const inverse::ParameterPoint& p, double* r) const override {
    // 1: the start's check, 2: the initial cost, 3: the start in the solver, 4-5: its two
    // perturbations, 6: the first trial step.
    const int call = ++calls_;
    if (call == 4 || call == 6) {
      ++failures_;
      return false;
    }
    return inner_->residuals(p, r);
  }
  bool residuals(const material::MaterialParams<inverse::Jet>&, inverse::Jet*) const override { return false; }
  bool supports_jets() const override { return false; }
  inverse::ExperimentCurve compare(const inverse::ParameterPoint& p) const override { return inner_->compare(p); }
  inverse::ExperimentCurve axes() const override { return inner_->axes(); }
  int failures() const { return failures_; }

 private:
  std::shared_ptr<inverse::Experiment> inner_;
  mutable std::atomic<int> calls_{0}, failures_{0};
};

// Failed forward runs in the middle of a fit do not end it: a failed perturbation makes its
// Jacobian column one-sided, a failed trial step is rejected, and the fit still ends at mu = 0.1.
TEST(FeFit, FailedRunsMidFitDoNotEndIt) {
  const TinyLineData fx = tiny_line_data("fx");
  const fs::path f = write_fit(fit_head(kFriction) + experiment(fx.scene, "data = \"" + fx.data.string() + "\"\nx = \"travel\"\ny = \"fx\"\nnoise = 1.0\n"));
  auto problem = inverse::read_fit_file(f.string());
  auto failing = std::make_shared<FailingEvaluations>(problem.experiments.front());
  problem.experiments.front() = failing;
  inverse::FitRunOptions options;
  options.threads = 1;  // the calls in a fixed order
  const auto r = inverse::run_fit(problem, options);
  std::printf("mu %.6f after %d failed evaluations, %d iterations\n", r.values[0], failing->failures(), r.iterations);
  EXPECT_EQ(failing->failures(), 2);
  ASSERT_TRUE(r.usable) << r.termination;
  EXPECT_NEAR(r.values[0], 0.1, 1e-4);
}

// Twin experiment on a cone: the central-third means of Ftheta / Fz of three contours of the small
// tiny cone made at mu = 0.1 (no noise) give back mu from 0.14 (Ftheta / Fz moves by about the
// change of mu: -0.233 at mu = 0.1, -0.254 at 0.12 on contour 1).
TEST(FeFit, TinyConeFrictionFromContourMeans) {
  const fs::path scene = test::write_tiny_cone(test::temp_path("cone.toml"), "", test::small_tiny_cone(3));
  const fs::path data = test::temp_path("means.csv");
  {
    auto sc = scene::read_scene(scene.string());
    ASSERT_EQ(sc->set_input("contact.friction", 0.1), "");
    inverse::SyntheticOptions o;
    o.y = "ftheta_over_fz";
    std::ofstream(data) << inverse::synthetic_contour_means_csv(*sc, o);
  }
  const fs::path f = write_fit(fit_head(kFriction) + experiment(scene, "contour_means = \"ftheta_over_fz\"\ndata = \"" + data.string() + "\"\nnoise = 0.001\n"));
  const auto problem = inverse::read_fit_file(f.string());
  inverse::FitRunOptions options;
  options.threads = 2;
  const auto r = inverse::run_fit(problem, options);
  std::printf("mu %.6f from 3 contour means (start 0.14), %d iterations, %ld scene runs, %.1f s\n", r.values[0], r.iterations, r.scene_runs,
              r.wall_seconds);
  ASSERT_TRUE(r.usable) << r.termination;
  EXPECT_NEAR(r.values[0], 0.1, 1e-4);
}

}  // namespace

// The answer of an FE evaluation job (MPI workers, fe_evaluation_job.hpp) comes back with the
// exact bits of every residual, -0 and the smallest subnormal included; bytes that are no answer
// (an empty reply, a job in the answer's place) are refused, not misread.
TEST(FeEvaluationJob, AnswersKeepEveryBitAndForeignBytesAreRefused) {
  inverse::FeEvaluationAnswer a;
  a.experiments.push_back({"drag", true, {0.1 + 0.2, -0.0, 4.9406564584124654e-324, -1e300}});
  a.experiments.push_back({"press", false, {}});
  a.runs.push_back({"line.toml", "drag", 0.25, true, false});
  a.failures.push_back({"line.toml", "contact.friction=0.5", "diverged", true});
  const inverse::FeEvaluationAnswer b = inverse::decode_fe_answer(inverse::encode_answer(a));
  ASSERT_EQ(b.experiments.size(), 2u);
  EXPECT_EQ(b.experiments[0].experiment, "drag");
  ASSERT_EQ(b.experiments[0].values.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(std::memcmp(&b.experiments[0].values[i], &a.experiments[0].values[i], sizeof(double)), 0) << i;
  EXPECT_FALSE(b.experiments[1].ok);
  ASSERT_EQ(b.runs.size(), 1u);
  EXPECT_TRUE(b.runs[0].retry);
  ASSERT_EQ(b.failures.size(), 1u);
  EXPECT_EQ(b.failures[0].message, "diverged");
  EXPECT_THROW(inverse::decode_fe_answer(""), std::runtime_error);
  EXPECT_THROW(inverse::decode_fe_answer(inverse::fe_evaluation_job("drag", {})), std::runtime_error);
  EXPECT_EQ(inverse::decode_fe_answer(inverse::failed_fe_answer("killed by signal 9")).error, "killed by signal 9");
}
