#pragma once
// The generated key reference (docs/reference/input-reference.md, `spifit inputs --markdown`): every scene
// kind with its named inputs (io/named_inputs.hpp) and observables, and the material parameters
// (material/material_inputs.hpp), from the tables the readers use.
#include "forward/scenes/common/scene.hpp"

#include <string>

namespace spifit::scene {

// The whole reference as Markdown.
std::string input_reference_markdown();
// One kind's inputs and observables as Markdown (its section of the reference).
std::string kind_reference_markdown(const SceneKind& kind);
// A Markdown table of observables.
std::string observables_markdown(const std::vector<Observable>& observables);

}  // namespace spifit::scene
