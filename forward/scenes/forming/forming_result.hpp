#pragma once
// The typed result of an indent, indent_line or line run (forming_scene.hpp): the tool force
// history (a half model's force mirrored to the whole sheet), the sections y = 0 at the named
// path points, the energy account and the run's counters.
#include "forward/io/series.hpp"
#include "forward/scenes/common/fe_scene_result.hpp"

#include <string>
#include <vector>

namespace spifit::scene {

struct PathSection {
  std::string point;  // the path point's name
  io::Series nodes;   // x0, x, y, z, thickness of the nodes on y = 0 (mid-surface) [mm]
  // A run with sensitivities: the derivatives of the nodes' x, z and thickness, one row per node
  // (in the order of `nodes`), one column per parameter; empty otherwise.
  Eigen::MatrixXd dx, dz, dthickness;
};

class FormingResult final : public FeSceneResult {
 public:
  nlohmann::json inputs;  // the scene as summary.json describes it
  std::string name, kind;
  int elements = 0;
  double path_length = 0.0, feed = 0.0;
  bool half = false;
  std::vector<PathSection> sections;

  nlohmann::json to_json() const override;
  std::string brief_report() const override;
  ResultCurve path_section(const std::string& point, const std::string& x, const std::string& y) const override;
};

}  // namespace spifit::scene
