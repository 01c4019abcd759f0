#include "forward/scenes/material_point/material_point_inputs.hpp"

#include "forward/scenes/common/scene_inputs.hpp"

namespace spifit::scene {
namespace {

using io::InputType;
using io::Range;
using Table = io::InputTable<MaterialPointScene>;

void add_scene(Table& t) {
  add_scene_inputs(t, {"tensile", "shear", "bauschinger", "plane_strain", "biaxial"}, SceneMaterialKey::optional);
  t.real({"scene.angle", {}, "deg", Range::closed(-180.0, 180.0), {}, "loading direction from the rolling direction", true},
         [](MaterialPointScene& s) -> double& { return s.setup.angle_deg; });
  t.custom({"scene.strain_path", {}, "", {}, {},
            "targets of the control strain from 0, e.g. [0.2, -0.2] (default 0.3; shear and bauschinger: 0.5, bauschinger requires it)", false},
           InputType::list);
  t.integer({"scene.increments", {}, "", Range::closed(1, 10000000), {}, "recorded increments over the whole path", false},
            [](MaterialPointScene& s) -> int& { return s.setup.increments; });
}

void add_solver(Table& t) {
  t.real({"solver.tolerance", {}, "", Range{0.0, 1e-2, true, true}, {}, "stress residual over max(|sigma|, sigma_F0)", false},
         [](MaterialPointScene& s) -> double& { return s.setup.driver.tolerance; });
  t.real({"solver.kinematic_substep", {}, "", Range::non_negative(), {},
          "bound on (back-stress decay rate) x d eps_p per sub-step (0: no accuracy sub-stepping)", false},
         [](MaterialPointScene& s) -> double& { return s.setup.driver.kinematic_substep; });
  t.integer({"solver.max_substeps", {}, "", Range{1.0, 1e9, false, false}, {}, "sub-steps per increment before the accuracy bound is waived", false},
            [](MaterialPointScene& s) -> int& { return s.setup.driver.max_substeps; });
  t.integer({"solver.max_cutbacks", {}, "", Range::closed(0, 60), {}, "halvings of one increment before the run fails", false},
            [](MaterialPointScene& s) -> int& { return s.setup.driver.max_cutbacks; });
  t.integer({"solver.max_newton_iterations", {}, "", Range{2.0, 1e6, false, false}, {}, "Newton iterations of the mixed control", false},
            [](MaterialPointScene& s) -> int& { return s.setup.driver.max_newton_iterations; });
  t.real({"solver.return_mapping_tolerance", {}, "", Range{0.0, 1e-3, true, true}, {}, "tolerance of the return mapping", false},
         [](MaterialPointScene& s) -> double& { return s.setup.driver.return_mapping.tolerance; });
}

Table make_table(MaterialPointKind kind) {
  Table t;
  add_scene(t);
  if (kind == MaterialPointKind::tensile) {
    t.real({"scene.r_value_strain", {}, "", Range::positive(), {}, "strain at which the r-value is evaluated", true},
           [](MaterialPointScene& s) -> double& { return s.setup.r_value_strain; });
    t.real({"scene.offset_strain", {}, "", Range{0.0, 0.1, true, true}, {}, "axial plastic strain of the offset yield stress", false},
           [](MaterialPointScene& s) -> double& { return s.setup.offset_strain; });
  }
  if (kind == MaterialPointKind::biaxial)
    t.real({"scene.stress_ratio", {}, "", Range::closed(-1.0, 1.0), {}, "sigma_ww / sigma_ll", true},
           [](MaterialPointScene& s) -> double& { return s.setup.stress_ratio; });
  add_solver(t);
  return t;
}

}  // namespace

const io::InputTable<MaterialPointScene>& material_point_inputs(MaterialPointKind kind) {
  // One table per kind, built on first use.
  switch (kind) {
    case MaterialPointKind::tensile: {
      static const Table t = make_table(kind);
      return t;
    }
    case MaterialPointKind::biaxial: {
      static const Table t = make_table(kind);
      return t;
    }
    default: {
      static const Table t = make_table(MaterialPointKind::shear);  // shear, bauschinger, plane_strain: the common keys
      return t;
    }
  }
}

}  // namespace spifit::scene
