#include "forward/scenes/material_point/material_point_file.hpp"

#include "forward/io/toml_reader.hpp"
#include "forward/scenes/material_point/material_point_inputs.hpp"

#include <cmath>

#include <filesystem>
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

MaterialPointScene read_material_point_scene(const std::string& path) {
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
  out.name = sc->string("name", std::filesystem::path(path).stem().string());
  out.description = sc->string("description", "");
  const std::string mat = sc->string("material");
  std::filesystem::path mp(mat);
  if (mp.is_relative()) mp = std::filesystem::path(path).parent_path() / mp;
  if (!std::filesystem::exists(mp)) sc->fail("material", "material card not found at " + mp.lexically_normal().string());
  out.card = material::load_material_card(mp.lexically_normal().string());
  inputs.read(*sc, "scene", out);
  read_strain_path(*sc, s);
  if (auto so = root.table("solver")) {
    so->allow_only(inputs.keys_of("solver"));
    inputs.read(*so, "solver", out);
  }
  return out;
}

}  // namespace spifit::scene
