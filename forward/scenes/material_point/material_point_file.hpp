#pragma once
// Reading a scene TOML file (schema: docs/reference/file-formats.md). Paths inside a scene are
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

// What a scene file without [scene] material gets: the default card C.3 + C.4, as the FE
// scenes (a run), or no card (a fit, whose card replaces the scene's; card stays empty).
enum class AbsentMaterial { default_card, no_card };

// Throws io::InputError naming file, key and value.
MaterialPointScene read_material_point_scene(const std::string& path, AbsentMaterial absent = AbsentMaterial::default_card);

}  // namespace spifit::scene
