#include "inverse/experiments/fe_experiment_file.hpp"

#include "forward/scenes/scene_registry.hpp"
#include "inverse/experiments/cone_section_experiment.hpp"
#include "inverse/experiments/fe_curve_data.hpp"
#include "inverse/experiments/measurement.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace spifit::inverse {
namespace {

using io::format_number;
using io::InputError;

std::string observable_names(const scene::SceneKind& k) {
  std::string out;
  for (const auto& o : k.observables) out += (out.empty() ? "" : ", ") + o.name;
  return out;
}

// "it has 3 contours (numbers 1 to 3)".
std::string contour_count(const scene::Scene& s) {
  const std::string n = std::to_string(s.contours());
  return "it has " + n + (s.contours() == 1 ? " contour (number 1)" : " contours (numbers 1 to " + n + ")");
}

std::unique_ptr<Experiment> scalar(const io::TomlTable& e, FeExperimentBase base) {
  const scene::SceneKind* kind = scene::find_scene_kind(base.scene->kind());
  FeScalarSpec s;
  static_cast<FeExperimentBase&>(s) = std::move(base);
  const std::string name = e.string("observable");
  s.observable = kind->find_observable(name);
  if (!s.observable) e.fail("observable", "not an observable of scene kind " + kind->name + " (known: " + observable_names(*kind) + ")");
  if (s.observable->counts_failed_runs) e.fail("observable", "a count of the run, not a measurement");
  using Needs = scene::Observable::Needs;
  if (s.observable->needs == Needs::window) {
    const auto w = e.number_list("window");
    if (w.size() != 2 || !(w[0] < w[1])) e.fail("window", "expected [from, to] of tool travel in mm with from < to");
    const auto path = s.scene->tool_centre_path();
    const double length = path->length();
    if (w[0] < 0.0 || w[1] > length + 1e-9)
      e.fail("window", "must lie inside the tool path's travel [0, " + format_number(length) + "] mm");
    s.options.window = std::array<double, 2>{w[0], w[1]};
  } else if (e.has("window")) {
    e.fail("window", name + " takes no travel window");
  }
  if (s.observable->needs == Needs::contours) {
    const auto c = e.number_list("contours");
    if (c.size() != 2 || c[0] < 1 || c[0] > c[1] || c[0] != std::floor(c[0]) || c[1] != std::floor(c[1]))
      e.fail("contours", "expected [first, last] contour numbers with 1 <= first <= last");
    if (c[1] > s.scene->contours()) e.fail("contours", "beyond the path of scene " + s.scene->file() + ": " + contour_count(*s.scene));
    s.options.contours = std::pair<int, int>{static_cast<int>(c[0]), static_cast<int>(c[1])};
  } else if (e.has("contours")) {
    e.fail("contours", name + " takes no contour range");
  }
  s.value = e.number("value");
  s.source = e.string("source", "");
  return make_fe_scalar_experiment(std::move(s));
}

// section = "C": the section y = 0 at a named path point of a forming scene.
std::unique_ptr<Experiment> section(const io::TomlTable& e, const std::string& path, FeExperimentBase base) {
  SectionSpec c;
  static_cast<FeExperimentBase&>(c) = std::move(base);
  c.point = e.string("section");
  const auto points = c.scene->section_points();
  if (std::find(points.begin(), points.end(), c.point) == points.end()) {
    std::string known;
    for (const auto& p : points) known += (known.empty() ? "" : ", ") + p;
    e.fail("section", "scene " + c.scene->name() + " takes no section at this path point (its [output] sections: " + (known.empty() ? "none" : known) + ")");
  }
  c.x = e.string("x", "x");
  c.y = e.string("y", "z");
  if (!is_section_abscissa(c.x)) e.fail("x", "not an abscissa of a section (known: x, x0)");
  if (!is_section_response(c.y)) e.fail("y", "not a column of a section (known: z, thickness)");
  const double half = 0.5 * c.scene->input("sheet.length");
  CurveData d = read_curve_data(e, path, c.x, c.y, -half, half, "mm (the sheet)", "mm", "mm");
  c.xs = std::move(d.xs);
  c.ys = std::move(d.ys);
  c.point_weights = std::move(d.weights);
  return make_section_experiment(std::move(c));
}

// contour_means = "ftheta": a cone's central-third contour means against the contour number.
std::unique_ptr<Experiment> contour_means(const io::TomlTable& e, const std::string& path, FeExperimentBase base) {
  ContourMeansSpec c;
  static_cast<FeExperimentBase&>(c) = std::move(base);
  if (c.scene->contours() == 0) e.fail("contour_means", "only for scenes with contours: scene " + c.scene->name() + " (kind " + c.scene->kind() + ") has none");
  c.y = e.string("contour_means");
  if (!scene::is_contour_mean(c.y)) e.fail("contour_means", std::string("not a contour mean (known: ") + scene::contour_mean_names() + ")");
  for (const char* k : {"x", "y"})
    if (e.has(k)) e.fail(k, "contour means take the columns contour and " + c.y + " of the data file");
  const bool ratio = c.y.size() > 7 && c.y.compare(c.y.size() - 7, 7, "_over_fz") == 0;
  CurveData d = read_curve_data(e, path, "contour", c.y, 1.0, 1e9, "(contours from 1)", "", ratio ? "" : "N");
  for (double k : d.xs) {
    if (k != std::floor(k)) e.fail("data", "contour numbers must be whole (" + format_number(k) + ")");
    if (k > c.scene->contours())
      e.fail("data", "column contour holds contour " + format_number(k) + ", beyond the path of scene " + c.scene->file() + ": " +
                         contour_count(*c.scene));
  }
  c.contours = std::move(d.xs);
  c.ys = std::move(d.ys);
  c.point_weights = std::move(d.weights);
  return make_contour_means_experiment(std::move(c));
}

}  // namespace

const std::vector<std::string>& fe_experiment_keys() {
  static const std::vector<std::string> keys{"name",   "scene",         "data",       "x",     "y",      "noise",    "weight",
                                             "weight_column", "observable", "value", "window", "contours", "source", "section", "contour_means", "noise_relative", "noise_column"};
  return keys;
}

std::unique_ptr<Experiment> read_fe_experiment(const io::TomlTable& e, const std::string& path, FeExperimentBase base) {
  if (!base.scene->tool_centre_path()) e.fail("scene", "scene kind " + base.scene->kind() + " has no tool to measure");
  if (e.has("observable")) {
    for (const char* k : {"data", "x", "y", "weight_column", "noise_relative", "noise_column"})
      if (e.has(k)) e.fail(k, "a scalar experiment (observable = ...) takes no curve keys");
    return scalar(e, std::move(base));
  }
  for (const char* k : {"value", "window", "contours"})
    if (e.has(k)) e.fail(k, "a curve (data = ...) takes no scalar keys; a scalar needs observable = ...");
  const bool cone_section = e.has("section") && base.scene->contours() > 0;
  if (e.has("noise_column") && !cone_section) e.fail("noise_column", "only for the sections of cone scenes (section = ...)");
  if (cone_section) return read_cone_section_experiment(e, path, std::move(base));
  if (e.has("section")) return section(e, path, std::move(base));
  if (e.has("contour_means")) return contour_means(e, path, std::move(base));
  ForceCurveSpec c;
  static_cast<FeExperimentBase&>(c) = std::move(base);
  c.x = e.string("x", "depth");
  c.y = e.string("y", "fz");
  if (!is_force_curve_abscissa(c.x)) e.fail("x", std::string("not an abscissa of a force curve (known: ") + force_curve_abscissa_names() + ")");
  if (!is_force_component(c.y)) e.fail("y", std::string("not a tool-force component (known: ") + force_component_names() + ")");
  const double t = c.scene->input("sheet.thickness"), radius = c.scene->input("tool.radius");
  const auto [lo, hi] = force_curve_range(*c.scene->tool_centre_path(), t, radius, c.x);
  CurveData d = read_curve_data(e, path, c.x, c.y, lo, hi,
                                std::string(force_curve_abscissa_unit(c.x)) + " of scene " + c.scene->name() +
                                    (c.x == "depth" ? " (the depth while the tool goes down)" : ""),
                                force_curve_abscissa_unit(c.x), "N");
  c.xs = std::move(d.xs);
  c.ys = std::move(d.ys);
  c.point_weights = std::move(d.weights);
  return make_force_curve_experiment(std::move(c));
}

}  // namespace spifit::inverse
