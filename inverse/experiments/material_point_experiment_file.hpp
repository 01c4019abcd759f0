#pragma once
// An [[experiment]] of a fit file on a material-point scene (tensile, shear, bauschinger, ...): a
// curve (data, x, y), a scalar (observable, value) or a table of scalars (observable, data, x:
// one run and one residual per row, the row's x a scene input such as the angle), each with the
// scene's angle overridden by `angle`. Schema in docs/reference/file-formats.md; errors name the file, key
// and value.
#include "forward/io/toml_reader.hpp"
#include "inverse/experiments/experiment.hpp"

#include <memory>
#include <string>

namespace spifit::inverse {

// What every material-point experiment names: the scene (its card is replaced by the fit's) and
// the conditioning, read and checked by the fit file's reader.
struct MaterialPointExperimentBase {
  std::string name;
  scene::MaterialPointScene scene;
  double noise = 0.0;           // measurement standard deviation; 0: the range of the data (curve, table) or |value|
  double noise_relative = 0.0;  // curves and tables: > 0, each y's standard deviation is this fraction of |y|
  double weight = 1.0;
};

// Rejects the keys experiment e may not hold for its form (curve, scalar or table).
void allow_material_point_keys(const io::TomlTable& e);

// The scene at scene_path as experiment e runs it: without a card when the file gives none (the
// fit's card replaces it), at e's `angle` when it has one.
scene::MaterialPointScene read_experiment_scene(const io::TomlTable& e, const std::string& scene_path);

// e: the [[experiment]] table of fit file `path`.
std::unique_ptr<Experiment> read_material_point_experiment(const io::TomlTable& e, const std::string& path, MaterialPointExperimentBase base);

}  // namespace spifit::inverse
