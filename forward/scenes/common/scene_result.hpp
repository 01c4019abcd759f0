#pragma once
// The typed result of a scene run (material point, shell benchmark, indent, line, cone): the
// series and values of the run in memory, with names and units, a JSON view (summary.json) and
// a one-line report for people (as Ceres's Summary::BriefReport). Files are one consumer of the
// result; the CLI, sweeps and fits read the typed result (scene_registry.hpp).
#include "forward/scenes/common/run_status.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace spifit::scene {

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

 protected:
  // status, message (unless ok or empty), warnings and wall_seconds into j.
  void add_status(nlohmann::json& j) const;
};

}  // namespace spifit::scene
