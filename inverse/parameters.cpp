#include "inverse/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spifit::inverse {

const std::vector<std::string>& known_parameter_names() {
  static const std::vector<std::string> names{"elastic.E", "elastic.nu", "hill.F",     "hill.G",  "hill.H",
                                              "hill.N",    "swift.K",    "swift.eps0", "swift.n", "af.CX",
                                              "af.Xsat",   "ziegler.CA", "ziegler.GA"};
  return names;
}

bool is_known_parameter(const std::string& name) {
  const auto& n = known_parameter_names();
  return std::find(n.begin(), n.end(), name) != n.end();
}

double parameter_value(const material::MaterialCard& card, const std::string& n) {
  const auto& m = card.params;
  if (n == "elastic.E") return m.E;
  if (n == "elastic.nu") return m.nu;
  if (n == "hill.F") return m.F;
  if (n == "hill.G") return m.G;
  if (n == "hill.H") return m.H;
  if (n == "hill.N") return m.N;
  if (n == "swift.K") return m.K;
  if (n == "swift.eps0") return m.eps0;
  if (n == "swift.n") return m.n;
  if (n == "af.CX") return m.CX;
  if (n == "af.Xsat") return m.Xsat;
  if (n == "ziegler.CA") return m.CA;
  if (n == "ziegler.GA") return m.GA;
  throw std::invalid_argument("unknown parameter " + n);
}

ParameterSet::ParameterSet(material::MaterialCard base, std::vector<ParameterSpec> specs, bool normalise_hill)
    : base_(std::move(base)), specs_(std::move(specs)), normalise_hill_(normalise_hill) {
  for (int i = 0; i < static_cast<int>(specs_.size()); ++i) {
    if (!specs_[i].fixed) free_.push_back(i);
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
