#pragma once
// One point of a fit's parameter space in physical values: the material parameters (the fit's
// card with the fitted values set) and the scene inputs a fit varies (contact.friction,
// contact.penalty, tool.radius, ...: named inputs of the FE scenes, docs/design/identification.md).
#include "forward/material/material_params.hpp"

#include <string>
#include <utility>
#include <vector>

namespace spifit::inverse {

struct ParameterPoint {
  material::MaterialParams<double> material;
  std::vector<std::pair<std::string, double>> scene;  // name, value; in the fit file's order
};

}  // namespace spifit::inverse
