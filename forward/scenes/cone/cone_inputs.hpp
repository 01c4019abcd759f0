#pragma once
// The named inputs of the cone scene (io/named_inputs.hpp): every key of a cone scene file with
// its unit, valid values and meaning.
#include "forward/io/named_inputs.hpp"
#include "forward/scenes/cone/cone_scene.hpp"

namespace spifit::scene {

const io::InputTable<ConeScene>& cone_inputs();

}  // namespace spifit::scene
