#pragma once
// TOML tables shared by the tool scenes (forming_scene, cone_scene): [contact] and [solver]. The callers keep their own allow_only lists (a
// scene may add keys) and their own fields; these functions read, check and fail with the
// file, key and value (io::InputError).
#include "forward/contact/shell_contact.hpp"
#include "forward/io/toml_reader.hpp"
#include "forward/material/material_card.hpp"
#include "forward/solver/linear_solver.hpp"
#include "forward/solver/newton_solver.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace spifit::scene {

// [scene] material: the card file relative to the scene file (default C.3 + C.4 of the
// bundled tree); a missing file fails on the key.
material::MaterialCard read_scene_material(const io::TomlTable& sc, const std::string& scene_path);

// penalty, friction, tangential_penalty, points, surface ("flat" | "phong"); validated.
void read_contact_table(const io::TomlTable& ct, contact::ContactOptions* contact);

// The [solver] keys, bound to the scene's own fields.
struct SolverFields {
  double& travel_per_increment;
  int& max_iterations;
  std::optional<solver::LinearSolverKind>& linear_solver;
  bool& extrapolate;
  bool& line_search;
  double& force_tolerance;
  double& displacement_tolerance;
  int& divergence_after;
  int* move_increments = nullptr;  // cone scenes only: the key move_increments (>= 0)
  bool* estimate_next_correction = nullptr;  // cone scenes only: NewtonOptions::estimate_next_correction
  double* stabilisation = nullptr;  // cone scenes only: NewtonOptions::stabilisation, in [0, 1]
};
// travel_per_increment, max_iterations, linear_solver, extrapolate, line_search,
// force_tolerance, displacement_tolerance, divergence_after, and move_increments,
// estimate_next_correction and stabilisation where bound (and no other key).
void read_solver_table(const io::TomlTable& so, const SolverFields& f);

// Newton options of a tool scene (any type with the SolverFields members) whose path is
// `length` mm long: the load factor is the travelled fraction of the path.
template <typename Scene>
solver::NewtonOptions tool_newton_options(const Scene& s, double length) {
  solver::NewtonOptions o;
  o.initial_increment = o.max_increment = std::min(1.0, s.travel_per_increment / length);
  o.min_increment = 1e-4 * o.initial_increment;
  o.max_iterations = s.max_iterations;
  o.extrapolate = s.extrapolate;
  o.line_search = s.line_search;
  o.force_tolerance = s.force_tolerance;
  o.displacement_tolerance = s.displacement_tolerance;
  o.divergence_after = s.divergence_after;
  if (s.linear_solver) o.linear_solver = *s.linear_solver;
  return o;
}

// The [contact] options as summary.json shows them: penalty, friction, points, surface.
nlohmann::json contact_json(const contact::ContactOptions& c);

}  // namespace spifit::scene
