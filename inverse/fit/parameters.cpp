#include "inverse/fit/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spifit::inverse {

bool is_known_parameter(const std::string& name) { return material::find_material_input(name) != nullptr; }

double parameter_value(const material::MaterialCard& card, const std::string& n) {
  const material::MaterialInput* in = material::find_material_input(n);
  if (!in) throw std::invalid_argument("unknown parameter " + n);
  if (const std::string why = material::why_not_held(card.params, *in); !why.empty()) throw std::invalid_argument(why);
  return material::material_field(card.params, in->field);
}

ParameterSet::ParameterSet(material::MaterialCard base, std::vector<ParameterSpec> specs, bool normalise_hill)
    : base_(std::move(base)), specs_(std::move(specs)), normalise_hill_(normalise_hill) {
  for (int i = 0; i < static_cast<int>(specs_.size()); ++i) {
    const ParameterSpec& s = specs_[static_cast<std::size_t>(i)];
    const material::MaterialInput* in = s.scene_input ? nullptr : material::find_material_input(s.name);
    if (!in && !s.scene_input) throw std::invalid_argument("unknown parameter " + s.name);
    if (in) {
      if (const std::string why = material::why_not_held(base_.params, *in); !why.empty()) throw std::invalid_argument(why);
    }
    inputs_.push_back(in);
    if (!s.fixed) free_.push_back(i);
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

ParameterPoint ParameterSet::point(const double* x) const {
  ParameterPoint p{apply(x), {}};
  std::vector<double> value(specs_.size());
  for (std::size_t i = 0; i < specs_.size(); ++i) value[i] = specs_[i].initial;
  for (int k = 0; k < num_free(); ++k) value[static_cast<std::size_t>(free_[k])] = to_physical(k, x[k]);
  for (std::size_t i = 0; i < specs_.size(); ++i)
    if (specs_[i].scene_input) p.scene.emplace_back(specs_[i].name, value[i]);
  return p;
}

ParameterPoint ParameterSet::point_at(const std::vector<double>& physical) const {
  std::vector<double> x = initial_internal();
  for (int k = 0; k < num_free() && k < static_cast<int>(physical.size()); ++k) x[k] = to_internal(k, physical[k]);
  return point(x.data());
}

bool ParameterSet::has_scene_inputs() const {
  return std::any_of(specs_.begin(), specs_.end(), [](const ParameterSpec& s) { return s.scene_input; });
}

}  // namespace spifit::inverse
