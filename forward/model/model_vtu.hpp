#pragma once
// The committed state of a shell model as a VTU frame (mesh/vtu_writer.hpp): nodal
// displacement, director and thickness; per element the largest equivalent plastic strain of
// its layers, the bottom, middle and top layer stresses (mean of the in-plane points, material
// frame), and each contribution's cell data (the tool's contact pressure).
#include "forward/mesh/vtu_writer.hpp"

namespace spifit::model {

class ShellModel;

mesh::VtuFrame vtu_frame(const ShellModel& model);

}  // namespace spifit::model
