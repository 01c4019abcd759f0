#include "forward/scenes/common/scene_tables.hpp"

#include <cmath>
#include <filesystem>
#include <utility>

namespace spifit::scene {

material::MaterialCard read_scene_material(const io::TomlTable& sc, const std::string& scene_path) {
  std::filesystem::path mp(sc.string("material", "../../../materials/aa3003o_c3c4.toml"));
  if (mp.is_relative()) mp = std::filesystem::path(scene_path).parent_path() / mp;
  if (!std::filesystem::exists(mp)) sc.fail("material", "material card not found at " + mp.lexically_normal().string());
  return material::load_material_card(mp.lexically_normal().string());
}

void read_contact_table(const io::TomlTable& ct, contact::ContactOptions* c) {
  if (ct.has("surface")) {
    const std::string surface = ct.string("surface");
    if (surface == "flat") c->surface = contact::ContactOptions::Surface::flat;
    else if (surface == "phong") c->surface = contact::ContactOptions::Surface::phong;
    else ct.fail("surface", "expected \"flat\" or \"phong\"");
  }
  c->penalty = ct.number("penalty", c->penalty);
  c->friction = ct.number("friction", c->friction);
  c->tangential_penalty = ct.number("tangential_penalty", c->tangential_penalty);
  c->points = ct.integer("points", c->points);
  if (const std::string err = c->validate(); !err.empty()) {
    const std::string key = err.substr(0, err.find(' '));
    ct.fail(ct.has(key) ? key : "penalty", err);
  }
}

void read_solver_table(const io::TomlTable& so, const SolverFields& f) {
  std::vector<std::string> keys{"travel_per_increment", "max_iterations", "linear_solver", "extrapolate", "line_search",
                                 "force_tolerance", "displacement_tolerance", "divergence_after"};
  if (f.move_increments) keys.push_back("move_increments");
  if (f.estimate_next_correction) keys.push_back("estimate_next_correction");
  if (f.stabilisation) keys.push_back("stabilisation");
  so.allow_only(keys);
  if (f.stabilisation) {
    *f.stabilisation = so.number("stabilisation", *f.stabilisation);
    if (!(*f.stabilisation >= 0.0 && *f.stabilisation <= 1.0))
      so.fail("stabilisation", "must be in [0, 1] (damping factor of an increment that failed at the minimum increment, x |diag K|; 0: off)");
  }
  if (f.move_increments) {
    *f.move_increments = so.integer("move_increments", *f.move_increments);
    if (*f.move_increments < 0 || *f.move_increments > 1000)
      so.fail("move_increments", "must be in [0, 1000] (increments per move between pie contours; 0: one per travel_per_increment)");
  }
  if (so.has("travel_per_increment")) {
    f.travel_per_increment = so.number("travel_per_increment");
    if (!(f.travel_per_increment > 0.0 && std::isfinite(f.travel_per_increment))) so.fail("travel_per_increment", "must be > 0");
  }
  f.max_iterations = so.integer("max_iterations", f.max_iterations);
  if (f.max_iterations < 1 || f.max_iterations > 1000) so.fail("max_iterations", "must be in [1, 1000]");
  if (so.has("linear_solver")) {
    solver::LinearSolverKind k{};
    if (!solver::linear_solver_from_string(so.string("linear_solver"), &k))
      so.fail("linear_solver", "expected \"auto\", \"umfpack\" or \"cholmod\"");
    f.linear_solver = k;
  }
  f.divergence_after = so.integer("divergence_after", f.divergence_after);
  if (f.divergence_after < 0 || f.divergence_after > 1000)
    so.fail("divergence_after", "must be in [0, 1000] (iterations before a growing residual cuts the increment back; 0: never)");
  f.extrapolate = so.boolean("extrapolate", f.extrapolate);
  if (f.estimate_next_correction) *f.estimate_next_correction = so.boolean("estimate_next_correction", *f.estimate_next_correction);
  f.line_search = so.boolean("line_search", f.line_search);
  for (auto [key, v] : {std::pair{"force_tolerance", &f.force_tolerance}, std::pair{"displacement_tolerance", &f.displacement_tolerance}}) {
    *v = so.number(key, *v);
    if (!(*v >= 1e-12 && *v <= 1e-2)) so.fail(key, "must lie in [1e-12, 1e-2]");
  }
}

nlohmann::json contact_json(const contact::ContactOptions& c) {
  return {{"penalty", c.penalty},
          {"friction", c.friction},
          {"points", c.points},
          {"surface", c.surface == contact::ContactOptions::Surface::phong ? "phong" : "flat"}};
}

}  // namespace spifit::scene
