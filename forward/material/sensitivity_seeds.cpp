#include "forward/material/sensitivity_seeds.hpp"

#include "forward/material/material_inputs.hpp"

#include <algorithm>
#include <stdexcept>

namespace spifit::material {

std::vector<FieldSeed> sensitivity_seeds(const MaterialParams<double>& card, const std::vector<std::string>& names, bool h_follows_g) {
  if (names.empty()) throw std::invalid_argument("no parameter named");
  if (names.size() > static_cast<std::size_t>(kSensitivitySlots))
    throw std::invalid_argument(std::to_string(names.size()) + " parameters; a run differentiates at most " + std::to_string(kSensitivitySlots));
  std::vector<FieldSeed> seeds;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& name = names[k];
    if (name.empty()) continue;
    if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(k), name) != names.begin() + static_cast<std::ptrdiff_t>(k))
      throw std::invalid_argument(name + " is named twice");
    const MaterialInput* in = find_material_input(name);
    if (!in) {
      std::string known;
      for (const auto& m : material_inputs())
        if (holds_input(card, m)) known += (known.empty() ? "" : ", ") + m.info.name;
      throw std::invalid_argument(name + " is not a material parameter; this card has " + known);
    }
    if (const std::string why = why_not_held(card, *in); !why.empty()) throw std::invalid_argument(why);
    SensitivityRow d = SensitivityRow::Zero();
    d(static_cast<Eigen::Index>(k)) = 1.0;
    seeds.push_back({in->field, d});
    for (const MaterialField& t : in->tied) seeds.push_back({t, d});
    if (h_follows_g && in->field.kind == MaterialField::G) seeds.push_back({MaterialField{MaterialField::H, -1, 0}, -d});
  }
  return seeds;
}

}  // namespace spifit::material
