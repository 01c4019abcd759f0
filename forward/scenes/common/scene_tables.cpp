#include "forward/scenes/common/scene_tables.hpp"

#include <cmath>
#include <filesystem>
#include <utility>

namespace spifit::scene {

material::MaterialCard read_scene_material(const io::TomlTable& sc, const std::string& scene_path, bool required) {
  std::filesystem::path mp(required ? sc.string("material") : sc.string("material", "../../../materials/aa3003o_c3c4.toml"));
  if (mp.is_relative()) mp = std::filesystem::path(scene_path).parent_path() / mp;
  if (!std::filesystem::exists(mp)) sc.fail("material", "material card not found at " + mp.lexically_normal().string());
  return material::load_material_card(mp.lexically_normal().string());
}

std::string InputViolation::text() const {
  if (key.empty()) return {};
  return key + (value.empty() ? "" : " = " + value) + ": " + message;
}

nlohmann::json contact_json(const contact::ContactOptions& c) {
  return {{"penalty", c.penalty},
          {"friction", c.friction},
          {"points", c.points},
          {"surface", c.surface == contact::ContactOptions::Surface::phong ? "phong" : "flat"}};
}

}  // namespace spifit::scene
