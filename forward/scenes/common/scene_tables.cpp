#include "forward/scenes/common/scene_tables.hpp"

#include <cmath>
#include <filesystem>
#include <utility>

namespace spifit::scene {

material::MaterialCard read_scene_material(const io::TomlTable& sc, const std::string& scene_path, bool required) {
  const char* default_card = "../../../materials/aa3003o_c3c4.toml";
  std::filesystem::path mp(required ? sc.string("material") : sc.string("material", default_card));
  if (mp.is_relative()) mp = std::filesystem::path(scene_path).parent_path() / mp;
  const std::string card = mp.lexically_normal().string();
  if (!std::filesystem::exists(mp) && !sc.has("material"))
    sc.fail("material", "not given, and the default card C.3 + C.4 is not at " + std::filesystem::absolute(mp).lexically_normal().string() + " (" +
                            default_card + " from the scene's folder): give the scene's card");
  if (!std::filesystem::exists(mp)) sc.fail("material", "material card not found at " + card);
  return material::load_material_card(card);
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
