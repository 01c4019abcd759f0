#pragma once
// Named access to the columns of a material-point curve (the names of curve.csv), used by
// the identification to compare a simulated column with a measured one.
#include "forward/scenes/material_point/material_point_run.hpp"

#include <optional>
#include <string>

namespace spifit::scene {

// Abscissae are data, never parameter-dependent: increment, strain, cumulative_strain.
template <typename T>
std::optional<double> curve_abscissa(const CurvePoint<T>& p, const std::string& name) {
  if (name == "increment") return double(p.increment);
  if (name == "strain") return p.control_strain;
  if (name == "cumulative_strain") return p.cumulative_strain;
  return std::nullopt;
}

template <typename T>
std::optional<T> curve_response(const CurvePoint<T>& p, const std::string& n) {
  if (n == "stress") return p.stress;
  if (n == "stress_kirchhoff") return p.stress_kirchhoff;
  if (n == "eps_ww") return p.strain_loading(1);
  if (n == "gamma_lw") return p.strain_loading(2);
  if (n == "eps_zz") return p.thickness_strain;
  if (n == "sig_xx") return p.stress_material(0);
  if (n == "sig_yy") return p.stress_material(1);
  if (n == "sig_xy") return p.stress_material(2);
  if (n == "eqps") return p.eqps;
  return std::nullopt;
}

// The unit of a column of curve.csv: MPa for stresses, "" for the increment, "-" for strains.
inline const char* curve_column_unit(const std::string& name) {
  if (name == "increment") return "";
  if (name.rfind("stress", 0) == 0 || name.rfind("sig_", 0) == 0) return "MPa";
  return "-";
}

inline const char* curve_abscissa_names() { return "increment, strain, cumulative_strain"; }
inline const char* curve_response_names() {
  return "stress, stress_kirchhoff, eps_ww, gamma_lw, eps_zz, sig_xx, sig_yy, sig_xy, eqps";
}

}  // namespace spifit::scene
