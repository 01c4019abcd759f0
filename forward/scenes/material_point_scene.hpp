#pragma once
// Runs a material-point scene file and writes DIR/summary.json and DIR/curve.csv
// (columns and units: docs/file-formats.md).
#include "forward/io/output_directory.hpp"
#include "forward/scenes/scene_file.hpp"

#include <nlohmann/json.hpp>

namespace spifit::scene {

struct SceneRunReport {
  bool ok = true;
  nlohmann::json summary;
};

// Never throws for numerical failures: the summary says "failed" with the message and no
// curve is left behind. Writes a "running" summary first, so a killed run is recognisable.
SceneRunReport run_material_point_scene(const MaterialPointScene& scene, const io::OutputDirectory& out);

// The curve as a CSV table (also used by tests and benchmarks).
std::string curve_csv(const MaterialPointResult<double>& result);

}  // namespace spifit::scene
