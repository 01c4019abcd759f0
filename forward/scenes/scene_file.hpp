#pragma once
// Reading a scene TOML file (schema: docs/file-formats.md). Paths inside a scene are
// relative to the scene file.
#include "forward/material/material_card.hpp"
#include "forward/scenes/material_point_test.hpp"

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
MaterialPointScene read_scene_file(const std::string& path);

// The [scene] kind of a scene file (material-point kinds or "shell_benchmark"); throws
// io::InputError for a missing file, a syntax error or a missing kind.
std::string scene_kind(const std::string& path);

// Kinds spifit knows; FE kinds are listed with the issue that brings them.
std::string known_scene_kinds();

}  // namespace spifit::scene
