#pragma once
// The named inputs of the material-point scene kinds (io/named_inputs.hpp): the keys of their
// scene files with unit, valid values and meaning. The tensile test adds the strain of its
// r-value and the offset of its yield stress, the biaxial test its stress ratio.
#include "forward/io/named_inputs.hpp"
#include "forward/scenes/material_point/material_point_file.hpp"

namespace spifit::scene {

const io::InputTable<MaterialPointScene>& material_point_inputs(MaterialPointKind kind);

}  // namespace spifit::scene
