#include "inverse/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spifit::inverse {

const std::vector<std::string>& known_parameter_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& m : material::material_inputs()) n.push_back(m.info.name);
    return n;
  }();
  return names;
}

bool is_known_parameter(const std::string& name) { return material::find_material_input(name) != nullptr; }

double parameter_value(const material::MaterialCard& card, const std::string& n) {
  const material::MaterialInput* in = material::find_material_input(n);
  if (!in) throw std::invalid_argument("unknown parameter " + n);
  return material::material_field(card.params, in->field);
}

ParameterSet::ParameterSet(material::MaterialCard base, std::vector<ParameterSpec> specs, bool normalise_hill)
    : base_(std::move(base)), specs_(std::move(specs)), normalise_hill_(normalise_hill) {
  for (int i = 0; i < static_cast<int>(specs_.size()); ++i) {
    const material::MaterialInput* in = material::find_material_input(specs_[static_cast<std::size_t>(i)].name);
    if (!in) throw std::invalid_argument("unknown parameter " + specs_[static_cast<std::size_t>(i)].name);
    inputs_.push_back(in);
    if (!specs_[static_cast<std::size_t>(i)].fixed) free_.push_back(i);
  }
}

std::vector<double> ParameterSet::initial_internal() const {
  std::vector<double> x;
  for (int k = 0; k < num_free(); ++k) x.push_back(to_internal(k, specs_[free_[k]].initial));
  return x;
}
std::vector<double> ParameterSet::lower_internal() const {
  std::vector<double> x;
  for (int k = 0; k < num_free(); ++k) x.push_back(to_internal(k, specs_[free_[k]].lower));
  return x;
}
std::vector<double> ParameterSet::upper_internal() const {
  std::vector<double> x;
  for (int k = 0; k < num_free(); ++k) x.push_back(to_internal(k, specs_[free_[k]].upper));
  return x;
}
double ParameterSet::to_physical(int k, double internal) const {
  return specs_[free_[k]].log_scale ? std::exp(internal) : internal;
}
double ParameterSet::to_internal(int k, double physical) const {
  return specs_[free_[k]].log_scale ? std::log(physical) : physical;
}
double ParameterSet::physical_per_internal(int k, double internal) const {
  return specs_[free_[k]].log_scale ? std::exp(internal) : 1.0;
}

material::MaterialCard ParameterSet::card_for(const std::vector<double>& internal) const {
  material::MaterialCard c = base_;
  c.params = apply(internal.data());
  return c;
}

}  // namespace spifit::inverse
