#pragma once
// What the tool scenes (forming_scene, cone_scene) share besides their named inputs
// (tool_scene_inputs.hpp): the material card of [scene], the Newton options from the [solver]
// fields, and [contact] as summary.json shows it.
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

// Newton options of a tool scene (any type with the [solver] fields of tool_scene_inputs.hpp)
// whose path is `length` mm long: the load factor is the travelled fraction of the path.
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
