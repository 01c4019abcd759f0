#include "forward/scenes/sensitivity_refusal.hpp"

#include "forward/io/input_error.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/material/sensitivity_seeds.hpp"
#include "forward/scenes/scene_registry.hpp"

#include <stdexcept>

namespace spifit::scene {

std::optional<SensitivityRefusal> sensitivity_refusal(const Scene& scene, const std::vector<std::string>& names, bool h_follows_g) {
  std::string joined;
  for (const auto& n : names) joined += (joined.empty() ? "" : ",") + n;
  auto refuse = [&](const std::string& why) { return SensitivityRefusal{"--sensitivities", joined, why}; };
  const SceneKind* kind = find_scene_kind(scene.kind());
  if (!kind || !kind->sensitivities || !scene.card())
    return refuse(kind && kind->fe_run ? scene.kind() + " scenes have no parameter sensitivities"
                                       : "FE scenes only (a material-point scene's parameter derivatives are exact Jets in fits already)");
  // A scene input other than the penalty (contact.friction, tool.radius, ...); unknown names are
  // the seeds' to name, with the card's parameters.
  for (const auto& n : names) {
    if (n.empty() || is_contact_sensitivity(n) || material::find_material_input(n)) continue;
    bool scene_input = true;
    try {
      (void)scene.input(n);
    } catch (const std::invalid_argument&) {
      scene_input = false;
    }
    if (scene_input)
      return refuse(n + " has no exact sensitivity: only the card's parameters, " + kPenaltySensitivity + " and " + kFrictionSensitivity + " have");
  }
  try {
    (void)material::sensitivity_seeds(scene.card()->params, card_sensitivity_names(names), h_follows_g);
    // The model's own refusals come when it is built.
    RunControl control;
    control.sensitivities = names;
    control.sensitivity_h_follows_g = h_follows_g;
    control.build_only = true;
    (void)scene.run(RunFiles(), control);
  } catch (const io::InputError& e) {
    return refuse(e.message());
  } catch (const std::invalid_argument& e) {
    return refuse(e.what());
  }
  return std::nullopt;
}

}  // namespace spifit::scene
