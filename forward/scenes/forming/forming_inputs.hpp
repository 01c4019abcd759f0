#pragma once
// The named inputs of the forming scenes indent, indent_line and line (io/named_inputs.hpp):
// every key of their scene files with its unit, valid values and meaning.
#include "forward/io/named_inputs.hpp"
#include "forward/scenes/forming/forming_scene.hpp"

namespace spifit::scene {

const io::InputTable<FormingScene>& forming_inputs();

}  // namespace spifit::scene
