#include "forward/scenes/common/scene_result.hpp"

namespace spifit::scene {

void SceneResult::add_status(nlohmann::json& j) const {
  j["status"] = to_string(status);
  if (!message.empty() && status != RunStatus::ok) j["message"] = message;
  j["warnings"] = warnings;
  j["wall_seconds"] = wall_seconds;
}

}  // namespace spifit::scene
