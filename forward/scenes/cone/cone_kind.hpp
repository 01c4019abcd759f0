#pragma once
// The scene kind cone in the registry (scene_registry.hpp): reading, running, named inputs and
// the observables sweeps and fits read.
#include "forward/scenes/common/scene.hpp"

namespace spifit::scene {

SceneKind cone_kind();

}  // namespace spifit::scene
