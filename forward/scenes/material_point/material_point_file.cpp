#include "forward/scenes/material_point/material_point_file.hpp"

#include "forward/io/toml_reader.hpp"
#include "forward/scenes/common/scene_inputs.hpp"
#include "forward/scenes/material_point/material_point_inputs.hpp"

#include <cmath>

namespace spifit::scene {

namespace {

// [scene] strain_path: targets of the control strain from 0 (defaults by kind).
void read_strain_path(const io::TomlTable& sc, MaterialPointSetup& s) {
  const bool shear_like = s.kind == MaterialPointKind::shear || s.kind == MaterialPointKind::bauschinger;
  if (sc.has("strain_path")) {
    s.strain_path = sc.number_list("strain_path");
  } else if (s.kind == MaterialPointKind::bauschinger) {
    sc.fail("strain_path", "required for bauschinger (e.g. [0.2, -0.2]: shear, then reverse shear)");
  } else {
    s.strain_path = {shear_like ? 0.5 : 0.3};
  }
  if (s.strain_path.empty()) sc.fail("strain_path", "must hold at least one target strain");
  double prev = 0.0;
  for (double t : s.strain_path) {
    if (t == prev) sc.fail("strain_path", "consecutive targets must differ (and the first must differ from 0)");
    if (std::abs(t) > 5.0) sc.fail("strain_path", "targets beyond |5| log strain are not meaningful for a material point");
    prev = t;
  }
  if (s.kind == MaterialPointKind::bauschinger && s.strain_path.size() < 2)
    sc.fail("strain_path", "bauschinger needs at least one reversal (two or more targets)");
  if (s.kind == MaterialPointKind::tensile && s.strain_path.front() < 0)
    sc.fail("strain_path", "a tensile test starts in tension (first target > 0)");
}

}  // namespace

MaterialPointScene read_material_point_scene(const std::string& path, AbsentMaterial absent) {
  const auto root = io::TomlTable::parse_file(path);
  root.allow_only({"scene", "solver"});
  const auto sc = root.table("scene");
  if (!sc) root.fail("scene", "required table [scene] is missing");
  MaterialPointScene out;
  out.file = path;
  const std::string kind = sc->string("kind");
  MaterialPointSetup& s = out.setup;
  if (!material_point_kind_from_string(kind, &s.kind)) sc->fail("kind", "expected a material-point kind: tensile, shear, bauschinger, plane_strain or biaxial");
  const auto& inputs = material_point_inputs(s.kind);
  sc->allow_only(inputs.keys_of("scene"));
  if (absent == AbsentMaterial::no_card && !sc->has("material")) read_scene_name(*sc, path, out);
  else read_scene_header(*sc, path, out);
  inputs.read(*sc, "scene", out);
  read_strain_path(*sc, s);
  read_input_tables(root, inputs, {"solver"}, out);
  return out;
}

}  // namespace spifit::scene
