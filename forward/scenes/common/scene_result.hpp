#pragma once
// The typed result of a scene run (material point, shell benchmark, indent, line, cone): the
// series and values of the run in memory, with names and units, a JSON view (summary.json) and
// a one-line report for people (as Ceres's Summary::BriefReport). Files are one consumer of the
// result; the CLI, sweeps and fits read the typed result (scene_registry.hpp).
#include "forward/io/series.hpp"
#include "forward/scenes/common/run_status.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace spifit::scene {

class ToolForceHistory;

// A curve read off a result (a section, the contour means): x increasing; empty when the result
// has no such curve.
struct ResultCurve {
  std::vector<double> x, y;
  // A run with sensitivities (RunControl::sensitivities): dx(i, k) = d x_i / d p_k, likewise dy;
  // no rows when the result holds no derivatives of this curve.
  Eigen::MatrixXd dx, dy;
};

// A section's nodes as a curve sorted by x (stable), empty when two nodes share an x (it folds
// over). dy (rows as xs, a column per parameter; null: none) gives the curve's derivatives, dx
// those of x (null with dy: x does not move).
ResultCurve sorted_section_curve(const std::vector<double>& xs, const std::vector<double>& ys, const Eigen::MatrixXd* dx,
                                 const Eigen::MatrixXd* dy);

// The components a contour mean can give: fr, ftheta, fz (polar, at the tool's polar angle), fx,
// fy, and the ratios ftheta_over_fz, fr_over_fz.
const char* contour_mean_names();
bool is_contour_mean(const std::string& y);

class SceneResult {
 public:
  virtual ~SceneResult() = default;
  RunStatus status = RunStatus::running;
  std::string message;                // failed: where and why
  std::vector<std::string> warnings;  // plausibility warnings of the inputs and the run
  double wall_seconds = 0.0;
  bool ok() const { return status == RunStatus::ok; }
  // summary.json (status, message, warnings and wall_seconds included).
  virtual nlohmann::json to_json() const = 0;
  // One line: what ran and its main numbers.
  virtual std::string brief_report() const = 0;

  // What fits, sweeps and synthetic measurements read off a result, asked by what it holds rather
  // than by its scene kind (null or empty when the result holds none):
  // the tool force history of an FE run;
  virtual const ToolForceHistory* tool_force() const { return nullptr; }
  // the tool force's parameter sensitivities after every increment of a run with
  // RunControl::sensitivities (the rows of sensitivities.csv, sensitivity_log.hpp);
  virtual const io::Series* force_sensitivities() const { return nullptr; }
  // read off it: the derivatives of force sample i (rows x, y, z; one column per parameter, in
  // RunControl::sensitivities' order), no columns when the result holds none for sample i;
  Eigen::Matrix<double, 3, Eigen::Dynamic> force_sensitivity(std::size_t i) const;
  // the section at a named path point (Scene::section_points()), x in {x, x0}, y in {z, thickness},
  // sorted by x; empty too when two nodes share an x (the section folds over);
  virtual ResultCurve path_section(const std::string& /*point*/, const std::string& /*x*/, const std::string& /*y*/) const { return {}; }
  // the section after contour K (1-based, Scene::contours()), x in {r, r0}, y in {z, thickness},
  // sorted by x; empty too when it folds over;
  virtual ResultCurve contour_section(int /*contour*/, const std::string& /*x*/, const std::string& /*y*/) const { return {}; }
  // one value per completed contour (x = 1, 2, ...), y one of contour_mean_names() (NaN for a
  // contour without samples).
  virtual ResultCurve contour_means(const std::string& /*y*/) const { return {}; }

 protected:
  // status, message (unless ok or empty), warnings and wall_seconds into j.
  void add_status(nlohmann::json& j) const;
};

}  // namespace spifit::scene
