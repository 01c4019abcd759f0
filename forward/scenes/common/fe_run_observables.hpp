#pragma once
// The observables every FE forming run gives (docs/design/architecture.md, "A new observable"): read off
// the FeSceneResult part of a kind's typed result, appended to the kind's own.
#include "forward/scenes/common/scene.hpp"
#include "forward/scenes/common/tool_force_history.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace spifit::scene {

// peak_fz, final_fz, max_penetration, newton_iterations, increments.
std::vector<Observable> fe_run_observables();

// o with the derivatives of force component k (0 x, 1 y, 2 z) at the sample `pick` chooses (an
// SceneResult::force_sensitivity there).
using SamplePick = std::function<std::optional<std::size_t>(const ToolForceHistory&)>;
Observable with_sample_derivatives(Observable o, int k, SamplePick pick);

}  // namespace spifit::scene
