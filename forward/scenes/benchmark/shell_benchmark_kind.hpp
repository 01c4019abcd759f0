#pragma once
// The scene kind shell_benchmark in the registry (scene_registry.hpp): the element obstacle
// course (shell_benchmarks.hpp) with its value against the published reference.
#include "forward/scenes/common/scene.hpp"

namespace spifit::scene {

SceneKind shell_benchmark_kind();

}  // namespace spifit::scene
