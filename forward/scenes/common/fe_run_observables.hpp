#pragma once
// The observables every FE forming run gives (docs/design/architecture.md, "A new observable"): read off
// the FeSceneResult part of a kind's typed result, appended to the kind's own.
#include "forward/scenes/common/scene.hpp"

#include <vector>

namespace spifit::scene {

// peak_fz, final_fz, max_penetration, newton_iterations, increments.
std::vector<Observable> fe_run_observables();

}  // namespace spifit::scene
