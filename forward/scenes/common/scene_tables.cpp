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

std::string to_string(FrictionTangent t) {
  switch (t) {
    case FrictionTangent::exact: return "exact";
    case FrictionTangent::symmetrised: return "symmetrised";
    case FrictionTangent::automatic: break;
  }
  return "auto";
}

bool friction_tangent_from_string(const std::string& s, FrictionTangent* t) {
  for (FrictionTangent v : {FrictionTangent::automatic, FrictionTangent::exact, FrictionTangent::symmetrised}) {
    if (s == to_string(v)) {
      *t = v;
      return true;
    }
  }
  return false;
}

bool symmetrised_tangent(FrictionTangent t, double friction) {
  if (t == FrictionTangent::automatic) return friction <= kSymmetrisedTangentFriction;
  return t == FrictionTangent::symmetrised;
}

nlohmann::json contact_json(const contact::ContactOptions& c) {
  return {{"penalty", c.penalty},
          {"friction", c.friction},
          {"points", c.points},
          {"surface", c.surface == contact::ContactOptions::Surface::phong ? "phong" : "flat"},
          {"method", c.method == contact::ContactOptions::Method::mst ? "mst" : "penalty"}};
}

}  // namespace spifit::scene
