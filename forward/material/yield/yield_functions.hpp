#pragma once
// The registry of yield functions beside Hill 1948. A function is one header declaring its
// coefficients, its equivalent stress with gradient and Hessian as templates on the scalar type,
// and its convexity check (yld2000_2d.hpp is the model), plus its line in YieldFunctionList below;
// the card reader, the named inputs, the return mapping and the reports find it here. Hill 1948
// (von Mises with its default coefficients) is not in the list: it is the quadratic default
// (law -1), whose coefficients F, G, H, L, M, N MaterialParams holds and whose return mapping
// solves a linear system per iteration (return_mapping.hpp).
#include "forward/material/law_registry.hpp"
#include "forward/material/material_params.hpp"
#include "forward/material/yield/yld2000_2d.hpp"

#include <initializer_list>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace spifit::material {

// One line per function.
using YieldFunctionList = std::tuple<Yld2000_2d>;

inline constexpr int kYieldFunctionCount = static_cast<int>(std::tuple_size_v<YieldFunctionList>);

// Calls f(Law{}) for the function with this index (which must be one: check active()).
template <typename F>
decltype(auto) visit_yield_function(int law, F&& f) {
  return visit_law<YieldFunctionList>(law, std::forward<F>(f));
}

template <typename Law>
constexpr int yield_function_index() {
  static_assert(Law::count <= kMaxYieldCoefficients, "raise kMaxYieldCoefficients");
  return law_index<YieldFunctionList, Law>();
}

// A function's coefficients in its declared order: make_yield_function<Yld2000_2d>({...}).
template <typename Law, typename T = double>
YieldFunction<T> make_yield_function(std::initializer_list<T> coefficients) {
  return make_law<YieldFunction<T>, yield_function_index<Law>()>(coefficients);
}

// sigma_eq, gradient and Hessian of the card's registered yield function at the plane-stress
// shifted stress xi (m.yield.active() must hold).
template <typename T>
void registered_yield_value(const MaterialParams<T>& m, const Eigen::Matrix<T, 3, 1>& xi, YieldValue<T>& out, bool hessian) {
  visit_yield_function(m.yield.law, [&](auto law) {
    decltype(law)::evaluate(m.yield.c.data(), xi, out, hessian);
    return 0;
  });
}

struct YieldFunctionInfo {
  int id = 0;
  std::string name;     // card table and fit-name prefix: "yld2000"
  std::string title;    // "Yld2000-2d (Barlat et al. 2003)"
  std::string formula;
  std::vector<LawCoefficient> coefficients;
  std::vector<double> defaults;
  std::string (*violation)(const double* c, int& coefficient) = nullptr;  // empty: a closed convex surface
};

const std::vector<YieldFunctionInfo>& yield_functions();
const YieldFunctionInfo& yield_function(int id);
const YieldFunctionInfo* find_yield_function(const std::string& name);
// "Hill 1948" or the function's title.
std::string yield_function_title(int id);

// What any plane-stress yield function of a card gives in closed form (Hill 1948 or a
// registered one): sigma_eq of a unit stress, and the r-value of a uniaxial tension at angle
// alpha (radians) from RD, from the flow direction.
double plane_stress_equivalent(const MaterialParams<double>& m, const Eigen::Vector3d& sigma);
double uniaxial_yield_factor(const MaterialParams<double>& m, double alpha);   // sigma_eq of sigma = 1 at alpha
double uniaxial_r_value(const MaterialParams<double>& m, double alpha);
double shear_yield_factor(const MaterialParams<double>& m);                    // sigma_eq of tau_xy = 1
double equibiaxial_yield_factor(const MaterialParams<double>& m);              // sigma_eq of sxx = syy = 1
double equibiaxial_r_value(const MaterialParams<double>& m);                    // d eps_yy / d eps_xx

}  // namespace spifit::material
