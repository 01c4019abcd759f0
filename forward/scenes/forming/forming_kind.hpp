#pragma once
// The scene kinds indent, indent_line and line in the registry (scene_registry.hpp): reading,
// running, named inputs and the observables sweeps and fits read.
#include "forward/scenes/common/scene.hpp"

#include <vector>

namespace spifit::scene {

std::vector<SceneKind> forming_kinds();

}  // namespace spifit::scene
