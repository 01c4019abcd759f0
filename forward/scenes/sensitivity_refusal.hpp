#pragma once
// Whether a scene can be run with exact parameter sensitivities (RunControl::sensitivities;
// docs/design/sensitivities.md) with respect to given names, asked before anything is written
// or a fit relies on it: the scene kind, friction, the names against the card and the contact
// penalty, and the model's own refusals (the explicit scheme, solid families), found by building
// the model without running it.
#include "forward/scenes/common/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace spifit::scene {

// What stands in the way: the input (key and value: "contact.friction" = 0.1, or
// "--sensitivities" and the names) and why.
struct SensitivityRefusal {
  std::string key, value, why;
};

// Nothing when a run of `scene` with RunControl::sensitivities = names (and
// sensitivity_h_follows_g) would differentiate; else the first reason it would refuse.
std::optional<SensitivityRefusal> sensitivity_refusal(const Scene& scene, const std::vector<std::string>& names, bool h_follows_g = false);

}  // namespace spifit::scene
