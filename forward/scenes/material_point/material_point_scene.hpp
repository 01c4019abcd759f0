#pragma once
// Running a material-point scene file: the typed result (the curve, r-value, yield points) and,
// with files, DIR/summary.json and DIR/curve.csv (columns and units: docs/reference/file-formats.md).
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/scene_result.hpp"
#include "forward/scenes/material_point/material_point_file.hpp"

namespace spifit::scene {

class MaterialPointSceneResult final : public SceneResult {
 public:
  MaterialPointScene scene;
  MaterialPointResult<double> result;
  nlohmann::json to_json() const override;
  std::string brief_report() const override;
};

// Never throws for numerical failures: the result says "failed" with the message and no curve
// is left behind. Writes a "running" summary first, so a killed run is recognisable.
MaterialPointSceneResult run_material_point_scene(const MaterialPointScene& scene, const RunFiles& files = {});

// The curve as a CSV table (also used by tests and benchmarks).
std::string curve_csv(const MaterialPointResult<double>& result);

}  // namespace spifit::scene
