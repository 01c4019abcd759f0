#pragma once
// The worked example of docs/design/architecture.md, "A new scene kind": `strip_press`, a strip clamped
// at both ends and pressed at mid-span by the spherical tool, with a new observable
// (mid_deflection). Everything a kind needs is in this folder; the product registers a kind with
// one line in forward/scenes/scene_registry.cpp, this test with register_scene_kind().
#include "forward/contact/shell_contact.hpp"
#include "forward/material/material_card.hpp"
#include "forward/scenes/common/scene.hpp"

#include <string>

namespace spifit::example {

// The scene file's data, with defaults.
struct StripPress {
  std::string name, file;
  material::MaterialCard card;
  double length = 40.0, width = 4.0, thickness = 1.0;  // mm
  int elements = 20;                                    // along the length (1 across per 2 mm of width)
  double tool_radius = 5.0, depth = 2.0, feed = 1.0;    // mm, mm, mm/s
  contact::ContactOptions contact;
  double travel_per_increment = 0.1;  // mm (the solver's [solver] key)
  int max_iterations = 25;
};

// The kind: reader, inputs, run and observables.
scene::SceneKind strip_press_kind();

}  // namespace spifit::example
