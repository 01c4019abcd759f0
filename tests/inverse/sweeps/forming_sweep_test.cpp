// Sweeps of the FE forming scenes: metrics equal those of direct runs, outputs per point in
// DIR/points/NNN, window metrics equal to those of force.csv, sensitivities, and input errors
// that name the file and the key before anything runs.
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/forming/forming_run.hpp"
#include "forward/scenes/forming/forming_scene.hpp"
#include "inverse/sweeps/sweep.hpp"
#include "tests/support/input_errors.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace spifit;
namespace fs = std::filesystem;

namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

// A temporary directory removed at the end of the test.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / ("spifit_forming_sweep_" + std::to_string(::getpid()) + "_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

// The §7.1 indent made tiny: 4 x 4 elements, 0.5 mm of travel in 10 increments.
fs::path write_tiny_indent(const fs::path& dir) {
  const fs::path f = dir / "tiny_indent.toml";
  std::ofstream(f) << "[scene]\nkind = \"indent\"\nmaterial = \"" << src("materials/aa3003o_c3c4.toml") << "\"\n"
                   << "[sheet]\nlength = 10.0\nthickness = 0.3\nelements = 4\n"
                   << "[tool]\nradius = 5.0\nfeed = 2.0\n"
                   << "[[path]]\nname = \"A\"\nx = 0.0\ny = 0.0\nz = 0.0\n"
                   << "[[path]]\nname = \"B\"\nx = 0.0\ny = 0.0\nz = -0.5\n"
                   << "[contact]\npenalty = 1000.0\nfriction = 0.0\npoints = 2\n"
                   << "[solver]\ntravel_per_increment = 0.05\n";
  return f;
}

fs::path write_sweep(const fs::path& dir, const std::string& body) {
  const fs::path f = dir / "sweep.toml";
  std::ofstream(f) << body;
  return f;
}

std::string sweep_head(const fs::path& scene, const std::string& metrics) {
  return "[sweep]\nscene = \"" + scene.string() + "\"\nmetrics = [" + metrics + "]\n";
}

std::size_t index_of(const std::vector<std::string>& v, const std::string& name) {
  return static_cast<std::size_t>(std::find(v.begin(), v.end(), name) - v.begin());
}

void expect_rel(double a, double b, double tol) { EXPECT_NEAR(a, b, tol * std::max(1.0, std::abs(b))) << a << " vs " << b; }

// force.csv rows: Fx, Fy, Fz and travel (= time x feed), parsed independently of the library.
struct ForceRow { double travel, fx, fy, fz; };
std::vector<ForceRow> read_force_csv(const fs::path& f, double feed) {
  std::ifstream in(f);
  std::vector<ForceRow> rows;
  bool header = false;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) { header = true; continue; }
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) v.push_back(std::stod(c));
    rows.push_back({v[0] * feed, v[4], v[5], v[6]});
  }
  return rows;
}

// The message of the InputError thrown by read_sweep_file (empty when none is thrown).
std::string read_error(const fs::path& f) {
  return test::input_error_of([&] { inverse::read_sweep_file(f.string()); }, "");
}

}  // namespace

TEST(FormingSweep, PenaltyPointsEqualDirectRunsAndWindowMetrics) {
  TempDir tmp("penalty");
  const fs::path scene = write_tiny_indent(tmp.path);
  const std::vector<std::string> names{"peak_fz", "final_fz", "peak_fx", "final_fx", "max_penetration", "newton_iterations",
                                       "increments", "mean_fx", "mean_fy", "mean_fz", "ripple_fz"};
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "\"" : ", \"") + n + "\"";
  const fs::path f = write_sweep(tmp.path, sweep_head(scene, list) + "window = [0.1, 0.4]\n[inputs.\"contact.penalty\"]\nvalues = [100.0, 1000.0]\n");
  const auto spec = inverse::read_sweep_file(f.string());
  EXPECT_EQ(spec.kind->family, "forming");
  EXPECT_FALSE(spec.sensitivities);  // default for forming sweeps
  const auto out = io::OutputDirectory::prepare((tmp.path / "out").string(), false);
  const auto r = inverse::run_sweep(spec, {1, &out, {}});
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_TRUE(r.sensitivities.empty());

  for (std::size_t i = 0; i < 2; ++i) {
    const auto& p = r.points[i];
    ASSERT_TRUE(p.ok) << p.message;
    EXPECT_TRUE(fs::exists(tmp.path / "out" / "points" / ("00" + std::to_string(i)) / "force.csv"));
    // The same scene run directly.
    auto sc = scene::read_forming_scene(scene.string());
    sc.contact.penalty = p.inputs[0];
    const auto direct = io::OutputDirectory::prepare((tmp.path / ("direct_" + std::to_string(i))).string(), false);
    const auto rep = scene::run_forming_scene(sc, scene::RunFiles(direct));
    ASSERT_TRUE(rep.ok());
    const auto s = rep.to_json();
    const auto m = [&](const std::string& n) { return p.metrics[index_of(names, n)]; };
    expect_rel(m("peak_fz"), s["peak_force"][2].get<double>(), 1e-12);
    expect_rel(m("peak_fx"), s["peak_force"][0].get<double>(), 1e-12);
    expect_rel(m("final_fz"), s["final_force"][2].get<double>(), 1e-12);
    expect_rel(m("final_fx"), s["final_force"][0].get<double>(), 1e-12);
    expect_rel(m("max_penetration"), s["max_penetration"].get<double>(), 1e-12);
    EXPECT_EQ(m("newton_iterations"), s["newton_iterations"].get<double>());
    EXPECT_EQ(m("increments"), s["increments"].get<double>());
    // Window metrics: the rows of force.csv with travel in [0.1, 0.4] mm.
    const auto rows = read_force_csv(direct.path() / "force.csv", sc.feed);
    double sx = 0, sy = 0, sz = 0, lo = 1e300, hi = -1e300;
    int n = 0;
    for (const auto& row : rows) {
      if (row.travel < 0.1 || row.travel > 0.4) continue;
      sx += row.fx, sy += row.fy, sz += row.fz, ++n;
      lo = std::min(lo, row.fz), hi = std::max(hi, row.fz);
    }
    ASSERT_GE(n, 5);
    expect_rel(m("mean_fx"), sx / n, 1e-12);
    expect_rel(m("mean_fy"), sy / n, 1e-12);
    expect_rel(m("mean_fz"), sz / n, 1e-12);
    expect_rel(m("ripple_fz"), (hi - lo) / (sz / n), 1e-12);
    EXPECT_GT(m("ripple_fz"), 0.0);  // Fz rises over the indent
  }
  // A stiffer penalty: less penetration, a larger force.
  EXPECT_GT(r.points[1].metrics[0], r.points[0].metrics[0]);
  EXPECT_LT(r.points[1].metrics[index_of(names, "max_penetration")], r.points[0].metrics[index_of(names, "max_penetration")]);
  // sweep.csv: inputs, metrics, wall_seconds, ok.
  const std::string csv = inverse::sweep_csv(spec, r);
  EXPECT_EQ(csv.substr(0, csv.find('\n')).rfind("contact.penalty,peak_fz,", 0), 0u) << csv;
  EXPECT_NE(csv.substr(0, csv.find('\n')).find(",wall_seconds,ok"), std::string::npos);

  // A window the tool never reaches: NaN for the window metrics, the others unaffected.
  scene::ObservableOptions far;
  far.window = std::array<double, 2>{10.0, 20.0};
  auto sc = scene::read_forming_scene(scene.string());
  sc.contact.penalty = r.points[0].inputs[0];
  const auto rep = scene::run_forming_scene(sc);  // in memory
  EXPECT_TRUE(std::isnan(spec.kind->find_observable("mean_fz")->value(rep, far)));
  EXPECT_TRUE(std::isnan(spec.kind->find_observable("ripple_fz")->value(rep, far)));
  EXPECT_EQ(spec.kind->find_observable("peak_fz")->value(rep, far), r.points[0].metrics[0]);
}

// Sensitivities at the scene's own values: d ln(peak Fz) / d ln(K_p) in (0, 1); friction's base
// is 0 (no logarithm) and an integer input has no relative step: NaN without runs.
TEST(FormingSweep, SensitivitiesAtTheScenesValues) {
  TempDir tmp("sens");
  const fs::path scene = write_tiny_indent(tmp.path);
  const fs::path f = write_sweep(tmp.path, sweep_head(scene, "\"peak_fz\"") +
                                               "sensitivities = true\n[inputs.\"contact.penalty\"]\nvalues = [1000.0]\n"
                                               "[inputs.\"contact.friction\"]\nvalues = [0.0]\n[inputs.\"contact.points\"]\nvalues = [2]\n");
  const auto spec = inverse::read_sweep_file(f.string());
  const auto out = io::OutputDirectory::prepare((tmp.path / "out").string(), false);
  const auto r = inverse::run_sweep(spec, {1, &out, {}});
  ASSERT_EQ(r.points.size(), 1u);
  ASSERT_EQ(r.sensitivities.size(), 3u);  // inputs in key order: friction, penalty, points
  const auto sens = [&](const std::string& input) {
    for (const auto& s : r.sensitivities)
      if (s.input == input) return s;
    ADD_FAILURE() << "no sensitivity for " << input;
    return inverse::Sensitivity{};
  };
  const auto kp = sens("contact.penalty");
  EXPECT_EQ(kp.base_input, 1000.0);
  EXPECT_EQ(kp.base_metric, r.points[0].metrics[0]);  // the base is the grid point here
  EXPECT_GT(kp.value, 0.0);
  EXPECT_LT(kp.value, 1.0);
  EXPECT_TRUE(std::isnan(sens("contact.friction").value));  // friction 0
  EXPECT_TRUE(std::isnan(sens("contact.points").value));    // integer input
  EXPECT_TRUE(fs::exists(tmp.path / "out" / "sensitivities" / "base" / "force.csv"));
  EXPECT_TRUE(fs::exists(tmp.path / "out" / "sensitivities" / "contact.penalty_up" / "summary.json"));
  EXPECT_FALSE(fs::exists(tmp.path / "out" / "sensitivities" / "contact.friction_up"));
}

// Exact sensitivities (exact_sensitivities = true): each point's d ln(metric) / d ln(input) from
// its own run with sensitivities, for the metrics that have derivatives; the base point's equal
// the central differences of the sweep without them (relative step 1e-3) within 1e-4, from one
// run instead of five.
TEST(FormingSweep, ExactSensitivitiesAtEveryPoint) {
  TempDir tmp("exact");
  const fs::path scene = write_tiny_indent(tmp.path);
  const std::string inputs = "[inputs.\"contact.penalty\"]\nvalues = [1000.0, 4000.0]\n[inputs.\"swift.K\"]\nvalues = [180.0]\n";
  const std::string head = sweep_head(scene, "\"peak_fz\", \"mean_fz\", \"max_penetration\"") + "window = [0.2, 0.5]\nsensitivities = true\n";
  const auto exact = inverse::read_sweep_file(write_sweep(tmp.path, head + "exact_sensitivities = true\n" + inputs).string());
  ASSERT_EQ(exact.exact_metrics, (std::vector<int>{0, 1}));  // max_penetration has no derivatives
  const auto re = inverse::run_sweep(exact, {1, nullptr, {}});
  const auto central = inverse::read_sweep_file(write_sweep(tmp.path, head + "relative_step = 1e-3\n" + inputs).string());
  const auto rc = inverse::run_sweep(central, {1, nullptr, {}});
  ASSERT_EQ(re.points.size(), 2u);
  for (std::size_t i = 0; i < re.points.size(); ++i) {
    ASSERT_TRUE(re.points[i].ok) << re.points[i].message;
    EXPECT_EQ(re.points[i].metrics, rc.points[i].metrics);  // the same runs, bit for bit
    ASSERT_EQ(re.points[i].log_derivatives.size(), 4u);     // (peak_fz, mean_fz) x (penalty, K)
  }
  // Kp's share falls as the penalty stiffens; K's stays near one (the force scales with K).
  EXPECT_GT(re.points[0].log_derivatives[0], re.points[1].log_derivatives[0]);
  EXPECT_NEAR(re.points[0].log_derivatives[1], 1.0, 0.3);
  ASSERT_EQ(re.sensitivities.size(), rc.sensitivities.size());
  for (std::size_t j = 0; j < re.sensitivities.size(); ++j) {
    const auto &a = re.sensitivities[j], &b = rc.sensitivities[j];
    ASSERT_EQ(a.input + a.metric, b.input + b.metric);
    std::printf("%s / %s: exact %.8g, central %.8g\n", a.metric.c_str(), a.input.c_str(), a.value, b.value);
    if (a.metric == "max_penetration") EXPECT_TRUE(std::isnan(a.value));
    else EXPECT_NEAR(a.value, b.value, 1e-4 * std::abs(b.value)) << a.metric << " " << a.input;
  }
  const std::string csv = inverse::sweep_csv(exact, re);
  EXPECT_NE(csv.find("dln(peak_fz)/dln(contact.penalty),dln(peak_fz)/dln(swift.K),dln(mean_fz)/dln(contact.penalty)"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("dln(max_penetration)"), std::string::npos);
  // The tool's radius, or no metric with derivatives: an input error naming the key.
  const std::string e = read_error(write_sweep(tmp.path, sweep_head(scene, "\"peak_fz\"") + "exact_sensitivities = true\n[inputs.\"tool.radius\"]\nvalues = [4.0]\n"));
  EXPECT_NE(e.find("exact_sensitivities"), std::string::npos) << e;
  EXPECT_NE(e.find("tool.radius"), std::string::npos) << e;
  const std::string counts = read_error(write_sweep(tmp.path, sweep_head(scene, "\"newton_iterations\"") + "exact_sensitivities = true\n" + inputs));
  EXPECT_NE(counts.find("none of the metrics has derivatives"), std::string::npos) << counts;
}

TEST(FormingSweep, InputErrorsNameFileAndKey) {
  TempDir tmp("errors");
  const fs::path scene = write_tiny_indent(tmp.path);
  const auto expect_error = [&](const std::string& body, const std::vector<std::string>& parts) {
    const fs::path f = write_sweep(tmp.path, body);
    const std::string e = read_error(f);
    ASSERT_FALSE(e.empty()) << body;
    EXPECT_NE(e.find(f.string()), std::string::npos) << e;
    for (const auto& p : parts) EXPECT_NE(e.find(p), std::string::npos) << "missing \"" << p << "\" in: " << e;
  };
  // Unknown scene key (the message lists the known ones).
  expect_error(sweep_head(scene, "\"peak_fz\"") + "[inputs.\"contact.penalt\"]\nvalues = [1.0]\n",
               {"inputs.contact.penalt", "contact.friction"});
  // Integer key with a fraction.
  expect_error(sweep_head(scene, "\"peak_fz\"") + "[inputs.\"contact.points\"]\nvalues = [2, 2.5]\n",
               {"inputs.contact.points.values", "2.5", "integer"});
  expect_error(sweep_head(scene, "\"peak_fz\"") + "[inputs.\"sheet.elements\"]\nfrom = 4\nto = 7\nsteps = 3\n",
               {"inputs.sheet.elements", "5.5", "integer"});
  // Values the scene reader would refuse fail at read time.
  expect_error(sweep_head(scene, "\"peak_fz\"") + "[inputs.\"contact.friction\"]\nvalues = [0.1, 3.0]\n",
               {"inputs.contact.friction.values", "3", "must lie in [0, 2]"});
  expect_error(sweep_head(scene, "\"peak_fz\"") + "[inputs.\"tool.radius\"]\nvalues = [0.0]\n", {"inputs.tool.radius.values", "> 0"});
  expect_error(sweep_head(scene, "\"peak_fz\"") + "[inputs.\"swift.n\"]\nvalues = [1.5]\n", {"inputs.swift.n.values", "1.5"});
  // Forming metric on a material-point scene, and the other way round.
  const fs::path tensile(src("experiments/aa3003o/scenes/tensile_45.toml"));
  expect_error(sweep_head(tensile, "\"peak_fz\"") + "[inputs.\"hill.N\"]\nvalues = [3.0]\n", {"sweep.metrics", "peak_fz"});
  expect_error(sweep_head(scene, "\"r_value\"") + "[inputs.\"contact.penalty\"]\nvalues = [1.0]\n", {"sweep.metrics", "r_value"});
  expect_error(sweep_head(tensile, "\"r_value\"") + "[inputs.\"contact.penalty\"]\nvalues = [1.0]\n", {"inputs.contact.penalty"});
  // Window metric without a window; a window on a material-point scene; a reversed window.
  expect_error(sweep_head(scene, "\"peak_fz\", \"mean_fz\"") + "[inputs.\"contact.penalty\"]\nvalues = [1.0]\n",
               {"sweep.metrics", "mean_fz", "window"});
  expect_error(sweep_head(tensile, "\"r_value\"") + "window = [0.0, 1.0]\n[inputs.\"hill.N\"]\nvalues = [3.0]\n", {"sweep.window"});
  expect_error(sweep_head(scene, "\"mean_fz\"") + "window = [2.0, 1.0]\n[inputs.\"contact.penalty\"]\nvalues = [1.0]\n", {"sweep.window"});
  // Unknown metric: the message lists the forming metrics.
  expect_error(sweep_head(scene, "\"peak_fy\"") + "[inputs.\"contact.penalty\"]\nvalues = [1.0]\n", {"sweep.metrics", "ripple_fz"});
}

// Checks across keys, which the scene readers make, reject a grid value at read time too
// (docs/design/architecture.md, "Typed results, kinds and named inputs"): the surface rule with an
// even thickness_points on a cone, and a sheet too small for the tool path of an indent.
TEST(FormingSweep, CrossKeyChecksRejectGridValuesAtReadTime) {
  TempDir tmp("cross_key");
  const fs::path cone = tmp.path / "tiny_cone.toml";
  std::ofstream(cone) << "[scene]\nkind = \"cone\"\nmaterial = \"" << src("materials/aa3003o_c3c4.toml") << "\"\n"
                      << "[cone]\nwall_angle = 45.0\nstepdown = 0.5\ncontours = 1\ntop_radius = 20.0\npie_angle = 90.0\n"
                      << "[sheet]\nthickness = 1.0\nelements_per_45deg = 8\nthickness_points = 3\nthickness_rule = \"surface\"\n";
  const fs::path f = write_sweep(tmp.path, sweep_head(cone, "\"peak_fz\"") + "[inputs.\"sheet.thickness_points\"]\nvalues = [4]\n");
  try {
    inverse::read_sweep_file(f.string());
    ADD_FAILURE() << "sheet.thickness_points = 4 with the surface rule accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), f.string());
    EXPECT_EQ(e.key(), "inputs.sheet.thickness_points.values");
    EXPECT_EQ(e.value(), "4");
    EXPECT_NE(e.message().find("odd number of thickness points"), std::string::npos) << e.what();
  }
  // The indent at x = 3 mm misses a sheet 4 mm wide (a tool of 1 mm radius, smaller than the sheet).
  const fs::path indent = tmp.path / "off_centre.toml";
  std::ofstream(indent) << "[scene]\nkind = \"indent\"\nmaterial = \"" << src("materials/aa3003o_c3c4.toml") << "\"\n"
                        << "[sheet]\nlength = 10.0\nthickness = 0.3\nelements = 4\n[tool]\nradius = 1.0\n"
                        << "[[path]]\nx = 3.0\ny = 0.0\nz = 0.0\n[[path]]\nx = 3.0\ny = 0.0\nz = -0.5\n";
  const fs::path g = write_sweep(tmp.path, sweep_head(indent, "\"peak_fz\"") + "[inputs.\"sheet.length\"]\nvalues = [10.0, 4.0]\n");
  const std::string e = read_error(g);
  for (const char* part : {"inputs.sheet.length.values = 4", "never goes below"}) EXPECT_NE(e.find(part), std::string::npos) << e;
  // A sheet narrower than the tool: the plausibility check names the tool.
  const fs::path h = write_sweep(tmp.path, sweep_head(indent, "\"peak_fz\"") + "[inputs.\"sheet.length\"]\nvalues = [10.0, 1.5]\n");
  const std::string narrow = read_error(h);
  for (const char* part : {"inputs.sheet.length.values = 1.5", "tool.radius = 1: the tool (diameter 2 mm) is larger than the sheet it forms (1.5 mm"})
    EXPECT_NE(narrow.find(part), std::string::npos) << narrow;
}

// The bundled FE sweep files read (the runs are on demand: README, docs/reference/cli.md).
TEST(FormingSweep, BundledSweepFilesRead) {
  const auto p = inverse::read_sweep_file(src("experiments/aa3003o/sweep_indent_penalty.toml"));
  ASSERT_EQ(p.inputs.size(), 1u);
  EXPECT_EQ(p.inputs[0].values.size(), 7u);
  EXPECT_EQ(p.inputs[0].values.front(), 10.0);
  EXPECT_EQ(p.inputs[0].values.back(), 1e7);
  EXPECT_EQ(p.inputs[0].values, (std::vector<double>{1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7}));  // decades exact
  const auto f = inverse::read_sweep_file(src("experiments/aa3003o/sweep_indent_line_friction.toml"));
  EXPECT_EQ(f.inputs[0].values, (std::vector<double>{0.0, 0.05, 0.1, 0.15}));
  const auto l = inverse::read_sweep_file(src("experiments/aa3003o/sweep_line_friction.toml"));
  ASSERT_TRUE(l.options.window);
  EXPECT_EQ((*l.options.window)[0], 25.0);
  EXPECT_EQ((*l.options.window)[1], 85.0);
  const auto c = inverse::read_sweep_file(src("experiments/aa3003o/sweep_cone70_friction.toml"));
  EXPECT_EQ(c.kind->name, "cone");
  EXPECT_EQ(c.inputs[0].values, (std::vector<double>{0.0, 0.05, 0.15}));
  ASSERT_TRUE(c.options.contours);
  EXPECT_EQ(c.options.contours->first, 3);
}
