#include "forward/scenes/common/scene_result.hpp"

namespace spifit::scene {

const char* contour_mean_names() { return "fr, ftheta, fz, fx, fy, ftheta_over_fz, fr_over_fz"; }
bool is_contour_mean(const std::string& y) {
  for (const char* n : {"fr", "ftheta", "fz", "fx", "fy", "ftheta_over_fz", "fr_over_fz"})
    if (y == n) return true;
  return false;
}

void SceneResult::add_status(nlohmann::json& j) const {
  j["status"] = to_string(status);
  if (!message.empty() && status != RunStatus::ok) j["message"] = message;
  j["warnings"] = warnings;
  j["wall_seconds"] = wall_seconds;
}

}  // namespace spifit::scene
