#include "inverse/experiments/cone_section_experiment.hpp"

#include "inverse/experiments/fe_curve_data.hpp"
#include "inverse/experiments/measurement.hpp"

#include <algorithm>
#include <cstdlib>

namespace spifit::inverse {
namespace {

using io::format_number;
using io::InputError;

// "last" or "contour K" with 1 <= K <= contours: K; else fails on key section.
int section_contour(const io::TomlTable& e, const std::string& scene_name, int contours) {
  const std::string v = e.string("section");
  const std::string takes = "scene " + scene_name + " takes one after each of its " + std::to_string(contours) +
                            " contours (\"last\" or \"contour K\", 1 <= K <= " + std::to_string(contours) + ")";
  if (v == "last") return contours;
  if (v.rfind("contour ", 0) != 0) e.fail("section", "not a section of a cone: " + takes);
  const std::string k = v.substr(8);
  char* end = nullptr;
  const long n = std::strtol(k.c_str(), &end, 10);
  if (k.empty() || *end != '\0' || n < 1 || n > contours) e.fail("section", "no such section: " + takes);
  return static_cast<int>(n);
}

// Point weights from per-point standard deviations (noise then 1 mm): w / std^2.
void read_noise_column(const io::TomlTable& e, const MeasurementTable& t, const std::string& data_path, ConeSectionSpec* c) {
  for (const char* k : {"noise", "noise_relative"})
    if (e.has(k)) e.fail(k, "noise_column gives each point's standard deviation; take one of them");
  const std::string col = e.string("noise_column");
  const std::vector<double> sd = t.column(col);
  if (t.units.count(col) && !t.units.at(col).empty() && t.units.at(col) != "mm")
    e.fail("noise_column", "column " + col + " is in " + t.units.at(col) + "; sections are compared in mm");
  if (c->point_weights.empty()) c->point_weights.assign(sd.size(), 1.0);
  for (std::size_t i = 0; i < sd.size(); ++i) {
    if (!(sd[i] > 0))
      throw InputError(data_path, "column " + col, format_number(sd[i]), "standard deviations must be > 0 (row " + std::to_string(i + 1) + ")");
    c->point_weights[i] /= sd[i] * sd[i];
  }
  c->noise = 1.0;
  c->noise_relative = 0.0;
}

// The measured (x, y): x strictly increasing inside [0, clamp radius]; y in mm; point weights.
void read_data(const io::TomlTable& e, const std::string& path, double clamp_radius, ConeSectionSpec* c) {
  CurveData d = read_curve_data(e, path, c->x, c->y, 0.0, clamp_radius, "mm (from the axis to the clamp)", "mm", "mm");
  c->xs = std::move(d.xs);
  c->ys = std::move(d.ys);
  c->point_weights = std::move(d.weights);
  if (e.has("noise_column")) read_noise_column(e, d.table, d.data_path, c);
}

}  // namespace

bool is_cone_section_abscissa(const std::string& x) { return x == "r" || x == "r0"; }
bool is_cone_section_response(const std::string& y) { return y == "z" || y == "thickness"; }


ForceCurve cone_section_curve(const scene::SceneResult& r, int contour, const std::string& x, const std::string& y) {
  return r.contour_section(contour, x, y);
}

std::unique_ptr<Experiment> make_cone_section_experiment(ConeSectionSpec s) {
  const int contour = s.contour;
  const std::string x = s.x, y = s.y;
  FeCurve curve{s.x, s.y, "mm", "mm", std::move(s.xs), std::move(s.ys), std::move(s.point_weights)};
  // Exact: the section's z and thickness carry their derivatives (ConeResult::contour_section).
  return make_fe_curve_experiment(
      s, "cone_section", std::move(curve),
      [contour, x, y](const scene::SceneResult& r, const ParameterPoint&) { return cone_section_curve(r, contour, x, y); }, true);
}

std::unique_ptr<Experiment> read_cone_section_experiment(const io::TomlTable& e, const std::string& path, FeExperimentBase base) {
  ConeSectionSpec c;
  static_cast<FeExperimentBase&>(c) = std::move(base);
  c.contour = section_contour(e, c.scene->name(), c.scene->contours());
  c.x = e.string("x", "r");
  c.y = e.string("y", "z");
  if (!is_cone_section_abscissa(c.x)) e.fail("x", "not an abscissa of a cone section (known: r, r0)");
  if (!is_cone_section_response(c.y)) e.fail("y", "not a column of a cone section (known: z, thickness)");
  read_data(e, path, c.scene->input("sheet.clamp_radius"), &c);
  return make_cone_section_experiment(std::move(c));
}

}  // namespace spifit::inverse
