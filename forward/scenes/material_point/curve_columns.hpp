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

// The words an axis shows for a column of curve.csv: simple shear (shear, bauschinger) is
// driven by the engineering shear strain gamma_lw and answers with the shear stress tau = sig_lw;
// the other kinds by an axial strain and its true stress. "" for a name that is no column.
inline std::string curve_column_words(MaterialPointKind kind, const std::string& name) {
  const bool shear = kind == MaterialPointKind::shear || kind == MaterialPointKind::bauschinger;
  if (name == "increment") return "increment";
  if (name == "strain") return shear ? "shear strain γ" : "strain ε";
  if (name == "cumulative_strain") return shear ? "cumulative shear strain Σ|Δγ|" : "cumulative strain Σ|Δε|";
  if (name == "stress") return shear ? "shear stress τ" : "true stress σ";
  if (name == "stress_kirchhoff") return shear ? "Kirchhoff shear stress τ" : "Kirchhoff stress";
  if (name == "eps_ww") return "width strain ε_ww";
  if (name == "gamma_lw") return "shear strain γ_lw";
  if (name == "eps_zz") return "thickness strain ε_zz";
  if (name == "sig_xx" || name == "sig_yy" || name == "sig_xy") return "σ_" + name.substr(4) + " (material axes)";
  if (name == "eqps") return "equivalent plastic strain";
  return "";
}

inline const char* curve_abscissa_names() { return "increment, strain, cumulative_strain"; }
inline const char* curve_response_names() {
  return "stress, stress_kirchhoff, eps_ww, gamma_lw, eps_zz, sig_xx, sig_yy, sig_xy, eqps";
}

}  // namespace spifit::scene
