#pragma once
// The committed state of an FE model as a VTU frame (mesh/vtu_writer.hpp): nodal displacement,
// then the element family's point and cell data (a shell's: director, thickness, the largest
// equivalent plastic strain of the layers, the bottom, middle and top layer stresses;
// ShellFamily::add_vtu_data), and each contribution's cell data (the tool's contact pressure).
// A model with sensitivities, given its parameters' names and values: per parameter p also the
// displacement's derivative "d(displacement)/d(p)" [mm per unit of p] and the scaled
// "p*d(displacement)/d(p)" [mm: the shape's change for a 100 % change of p, to first order],
// after the displacement.
#include "forward/mesh/vtu_writer.hpp"

#include <string>
#include <vector>

namespace spifit::model {

class FeModel;

mesh::VtuFrame vtu_frame(const FeModel& model, const std::vector<std::string>& sensitivity_names = {},
                         const std::vector<double>& sensitivity_values = {});

}  // namespace spifit::model
