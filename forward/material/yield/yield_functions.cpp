#include "forward/material/yield/yield_functions.hpp"

#include "forward/material/stress_space.hpp"

#include <cmath>

namespace spifit::material {

const std::vector<YieldFunctionInfo>& yield_functions() {
  static const std::vector<YieldFunctionInfo> laws = [] {
    std::vector<YieldFunctionInfo> out;
    for_each_law<YieldFunctionList>([&](auto law, int id) {
      using Law = decltype(law);
      out.push_back({id, Law::name, Law::title, Law::formula, Law::coefficients(), Law::defaults(), &Law::violation});
    });
    return out;
  }();
  return laws;
}

const YieldFunctionInfo& yield_function(int id) { return law_info_at(yield_functions(), id, "yield function"); }

const YieldFunctionInfo* find_yield_function(const std::string& name) { return find_law_info(yield_functions(), name); }

std::string yield_function_title(int id) { return id < 0 ? "Hill 1948" : yield_function(id).title; }

namespace {

// sigma_eq and its gradient (the flow direction, engineering shear) at sigma.
YieldValue<double> plane_stress_value(const MaterialParams<double>& m, const Eigen::Vector3d& sigma) {
  YieldValue<double> v;
  if (m.yield.active()) {
    registered_yield_value(m, sigma, v, false);
    return v;
  }
  const Eigen::Matrix3d P = StressSpace<double, 3>::hill(m);
  v.value = std::sqrt(std::max(0.0, 0.5 * sigma.dot(P * sigma)));
  if (v.value > 0.0) v.gradient = P * sigma / (2.0 * v.value);
  return v;
}

Eigen::Vector3d uniaxial(double alpha) {
  const double c = std::cos(alpha), s = std::sin(alpha);
  return {c * c, s * s, c * s};
}

}  // namespace

double plane_stress_equivalent(const MaterialParams<double>& m, const Eigen::Vector3d& sigma) { return plane_stress_value(m, sigma).value; }

double uniaxial_yield_factor(const MaterialParams<double>& m, double alpha) { return plane_stress_equivalent(m, uniaxial(alpha)); }

double uniaxial_r_value(const MaterialParams<double>& m, double alpha) {
  const Eigen::Vector3d n = plane_stress_value(m, uniaxial(alpha)).gradient;
  const double c = std::cos(alpha), s = std::sin(alpha);
  const double width = s * s * n(0) + c * c * n(1) - c * s * n(2);  // strain rate across the tension
  return width / -(n(0) + n(1));
}

double shear_yield_factor(const MaterialParams<double>& m) { return plane_stress_equivalent(m, Eigen::Vector3d(0.0, 0.0, 1.0)); }

double equibiaxial_yield_factor(const MaterialParams<double>& m) { return plane_stress_equivalent(m, Eigen::Vector3d(1.0, 1.0, 0.0)); }

double equibiaxial_r_value(const MaterialParams<double>& m) {
  const Eigen::Vector3d n = plane_stress_value(m, Eigen::Vector3d(1.0, 1.0, 0.0)).gradient;
  return n(1) / n(0);
}

}  // namespace spifit::material
