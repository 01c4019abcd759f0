#pragma once
// The seeds of a run's parameter sensitivities (docs/design/sensitivities.md): each named
// material parameter ("swift.K", material_inputs.hpp) gets the next derivative slot, set on its
// field and on the fields tied to it (hill.N sets L and M). hill.H stays a parameter of its own
// unless h_follows_g: then hill.G also moves H = 2 - G (a fit with normalise_hill).
#include "forward/material/material_params.hpp"
#include "forward/material/sensitivity_scalar.hpp"

#include <string>
#include <vector>

namespace spifit::material {

// The seeds of `names` in that order (an empty name keeps its slot for a parameter outside the
// card, e.g. the contact's penalty); std::invalid_argument with the reason for an unknown name,
// a parameter the card does not hold, a repeated name, or more than kSensitivitySlots names.
std::vector<FieldSeed> sensitivity_seeds(const MaterialParams<double>& card, const std::vector<std::string>& names, bool h_follows_g = false);

}  // namespace spifit::material
