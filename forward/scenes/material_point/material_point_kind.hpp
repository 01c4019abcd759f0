#pragma once
// The material-point scene kinds (tensile, shear, bauschinger, plane_strain, biaxial) in the
// registry (scene_registry.hpp): reading, running, named inputs and the observables sweeps and
// fits read.
#include "forward/scenes/common/scene.hpp"

#include <vector>

namespace spifit::scene {

std::vector<SceneKind> material_point_kinds();

}  // namespace spifit::scene
