// The parts of material_point_run.hpp that are not templates: kind names, the loading control
// of each kind and the setup's checks.
#include "forward/scenes/material_point/material_point_run.hpp"

#include <numbers>
#include <stdexcept>

namespace spifit::scene {

std::string to_string(MaterialPointKind k) {
  switch (k) {
    case MaterialPointKind::tensile: return "tensile";
    case MaterialPointKind::shear: return "shear";
    case MaterialPointKind::bauschinger: return "bauschinger";
    case MaterialPointKind::plane_strain: return "plane_strain";
    case MaterialPointKind::biaxial: return "biaxial";
  }
  return "?";
}

bool material_point_kind_from_string(const std::string& s, MaterialPointKind* k) {
  for (auto kind : {MaterialPointKind::tensile, MaterialPointKind::shear, MaterialPointKind::bauschinger,
                    MaterialPointKind::plane_strain, MaterialPointKind::biaxial}) {
    if (s == to_string(kind)) { *k = kind; return true; }
  }
  return false;
}

LoadingControl loading_control(const MaterialPointSetup& setup) {
  LoadingControl c;
  c.alpha = setup.angle_deg * std::numbers::pi / 180.0;
  using R = ComponentRole;
  switch (setup.kind) {
    case MaterialPointKind::tensile:  // sigma_ww = sigma_lw = 0
      c.control = 0; c.role[0] = R::control; c.role[1] = R::stress_ratio; c.role[2] = R::stress_ratio;
      break;
    case MaterialPointKind::biaxial:  // sigma_ww = ratio sigma_ll, sigma_lw = 0
      c.control = 0; c.role[0] = R::control; c.role[1] = R::stress_ratio; c.role[2] = R::stress_ratio;
      c.ratio[1] = setup.stress_ratio;
      break;
    case MaterialPointKind::plane_strain:  // eps_ww = 0, sigma_lw = 0
      c.control = 0; c.role[0] = R::control; c.role[1] = R::zero_strain; c.role[2] = R::stress_ratio;
      break;
    case MaterialPointKind::shear:
    case MaterialPointKind::bauschinger:  // eps_ll = eps_ww = 0, gamma_lw prescribed
      c.control = 2; c.role[0] = R::zero_strain; c.role[1] = R::zero_strain; c.role[2] = R::control;
      break;
  }
  return c;
}

void check_setup(const MaterialPointSetup& s) {
  if (s.strain_path.empty()) throw std::invalid_argument("strain_path is empty");
  if (s.increments < 1) throw std::invalid_argument("increments must be >= 1");
  double prev = 0.0;
  for (double t : s.strain_path) {
    if (t == prev) throw std::invalid_argument("strain_path repeats a value");
    prev = t;
  }
}

}  // namespace spifit::scene
