#pragma once
// What a run with sensitivities (spifit run --sensitivities) says on the terminal beside its
// one-line report: the derivatives of its dominant peak force component, raw and scaled by the
// parameter's value, read off the result's sensitivity table (sensitivities.csv holds every
// increment's).
#include "forward/scenes/common/scene_result.hpp"

#include <string>

namespace spifit::scene {

// Lines (each "  ..." ending in a newline) naming the component of ToolForceHistory::peak() of
// largest magnitude, its sample's time and, per parameter, dF/dp with its unit and p dF/dp in N;
// empty when the result holds no sensitivities or no force.
std::string sensitivity_brief(const SceneResult& result);

}  // namespace spifit::scene
