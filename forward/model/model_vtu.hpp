#pragma once
// The committed state of an FE model as a VTU frame (mesh/vtu_writer.hpp): nodal displacement,
// then the element family's point and cell data (a shell's: director, thickness, the largest
// equivalent plastic strain of the layers, the bottom, middle and top layer stresses;
// ShellFamily::add_vtu_data), and each contribution's cell data (the tool's contact pressure).
#include "forward/mesh/vtu_writer.hpp"

namespace spifit::model {

class FeModel;

mesh::VtuFrame vtu_frame(const FeModel& model);

}  // namespace spifit::model
