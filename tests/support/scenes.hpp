#pragma once
#include "forward/scenes/material_point/material_point_run.hpp"

#include <numbers>

namespace spifit::test {

inline scene::MaterialPointSetup tensile(double angle_deg, std::vector<double> path = {0.3}, int increments = 200) {
  scene::MaterialPointSetup s;
  s.kind = scene::MaterialPointKind::tensile;
  s.angle_deg = angle_deg;
  s.strain_path = std::move(path);
  s.increments = increments;
  return s;
}

inline scene::MaterialPointSetup shear(double angle_deg, std::vector<double> path, int increments = 200) {
  scene::MaterialPointSetup s;
  s.kind = path.size() > 1 ? scene::MaterialPointKind::bauschinger : scene::MaterialPointKind::shear;
  s.angle_deg = angle_deg;
  s.strain_path = std::move(path);
  s.increments = increments;
  return s;
}

inline double deg(double d) { return d * std::numbers::pi / 180.0; }

}  // namespace spifit::test
