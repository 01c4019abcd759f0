#pragma once
// Reading a scene TOML file (schema: docs/file-formats.md). Paths inside a scene are
// relative to the scene file.
#include "forward/material/material_card.hpp"
#include "forward/scenes/material_point/material_point_run.hpp"

#include <string>

namespace spifit::scene {

struct MaterialPointScene {
  std::string name;
  std::string description;
  std::string file;
  material::MaterialCard card;
  MaterialPointSetup setup;
};

// Throws io::InputError naming file, key and value.
MaterialPointScene read_material_point_scene(const std::string& path);

}  // namespace spifit::scene
