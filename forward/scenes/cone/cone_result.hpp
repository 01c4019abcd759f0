#pragma once
// The typed result of a cone run (cone_run.hpp): the tool force history with its polar
// components, the central-third means of the completed contours and the steady state over a
// contour range (thesis §8.3, §9.3), the section, stage and element-history series, the energy
// account and the run's counters.
#include "forward/io/series.hpp"
#include "forward/scenes/common/fe_scene_result.hpp"
#include "forward/scenes/cone/cone_observables.hpp"
#include "forward/scenes/cone/cone_sections.hpp"

#include <optional>
#include <string>
#include <vector>

namespace spifit::scene {

class ConeResult final : public FeSceneResult {
 public:
  nlohmann::json inputs;  // the scene as summary.json describes it
  std::string name;
  int elements = 0;
  int contours_total = 0;
  // force: the real tool's (a pie's virtual copies included), not scaled by 360 / pie angle.
  Eigen::Vector3d peak_polar = Eigen::Vector3d::Zero();  // (r, theta, z), largest magnitude per component
  std::vector<ContourMean> contours;  // completed contours
  std::optional<SteadyState> steady_state;
  io::Series sections, stages, history;  // sections.csv, stages.csv, history.csv
  std::vector<ConeSection> section_profiles;  // sections/section_s*_c*.csv: after each completed contour, path order
  nlohmann::json observables;            // section angle, last section, stages, history element
  // A run with sensitivities: d(centre depth)/dp at the end of the last stage reached (stages.csv's
  // last row), in RunControl::sensitivities' order; else empty.
  Eigen::RowVectorXd centre_depth_sensitivity;

  Eigen::Vector3d final_polar_force() const;
  nlohmann::json to_json() const override;
  std::string brief_report() const override;
  ResultCurve contour_section(int contour, const std::string& x, const std::string& y) const override;
  ResultCurve contour_means(const std::string& y) const override;
};

}  // namespace spifit::scene
