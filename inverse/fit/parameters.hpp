#pragma once
// Named, bounded parameters of an identification (docs/design/identification.md) and their mapping
// between the optimiser's vector (internal coordinates: log of the value for log-scaled
// parameters) and a material card. The names, units and ties are the material law's table
// (forward/material/material_inputs.hpp: hill.N also sets L and M). Normalisation G + H = 2 is
// eliminated by fitting hill.G and setting H = 2 - G (never handed to the optimiser as a
// constraint). A parameter may also be a scene input (contact.friction, ...) of the FE scenes
// of the fit: the fit file's reader checks the name against those scenes' input tables.
#include "forward/material/material_card.hpp"
#include "forward/material/material_inputs.hpp"
#include "inverse/runs/parameter_point.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace spifit::inverse {

struct ParameterSpec {
  std::string name;     // e.g. "swift.K"
  double initial = 0;   // physical value where the fit starts
  double lower = 0;     // physical bounds (finite)
  double upper = 0;
  bool fixed = false;
  bool log_scale = false;  // optimise ln(value) (needs lower > 0)
  bool scene_input = false;  // a named input of the FE scenes, not of the material card
};

// Whether spifit knows a material parameter by this name (material_inputs()).
bool is_known_parameter(const std::string& name);
// Current value of a named parameter in a card.
double parameter_value(const material::MaterialCard& card, const std::string& name);

class ParameterSet {
 public:
  // base: the card whose values are used for everything not fitted. std::invalid_argument for
  // a name that is not a material parameter (unless the spec is a scene input).
  ParameterSet(material::MaterialCard base, std::vector<ParameterSpec> specs, bool normalise_hill);

  const std::vector<ParameterSpec>& specs() const { return specs_; }
  const std::vector<int>& free_indices() const { return free_; }  // into specs()
  int num_free() const { return static_cast<int>(free_.size()); }
  bool normalise_hill() const { return normalise_hill_; }
  const material::MaterialCard& base() const { return base_; }

  std::vector<double> initial_internal() const;
  std::vector<double> lower_internal() const;
  std::vector<double> upper_internal() const;
  double to_physical(int free_index, double internal) const;
  double to_internal(int free_index, double physical) const;
  // d physical / d internal at an internal value (1, or the value for log scaling).
  double physical_per_internal(int free_index, double internal) const;

  // Material parameters for an internal vector (templated for Jets).
  template <typename T>
  material::MaterialParams<T> apply(const T* x) const {
    using std::exp;
    material::MaterialParams<T> m = base_.params.template cast<T>();
    for (std::size_t i = 0; i < specs_.size(); ++i)
      if (specs_[i].fixed && inputs_[i]) material::set_material_input(m, *inputs_[i], T(specs_[i].initial));
    for (int k = 0; k < num_free(); ++k) {
      const auto i = static_cast<std::size_t>(free_[k]);
      if (inputs_[i]) material::set_material_input(m, *inputs_[i], specs_[i].log_scale ? T(exp(x[k])) : x[k]);
    }
    if (normalise_hill_) m.H = 2.0 - m.G;
    return m;
  }
  material::MaterialCard card_for(const std::vector<double>& internal) const;
  // The material parameters and the scene inputs at an internal vector.
  ParameterPoint point(const double* internal) const;
  // The same at physical values of the free parameters (a FitResult's initial or values).
  ParameterPoint point_at(const std::vector<double>& physical) const;
  bool has_scene_inputs() const;

 private:
  material::MaterialCard base_;
  std::vector<ParameterSpec> specs_;
  std::vector<const material::MaterialInput*> inputs_;  // per spec; null for a scene input
  std::vector<int> free_;
  bool normalise_hill_ = true;
};

}  // namespace spifit::inverse
