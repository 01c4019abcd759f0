#pragma once
// What the tool scenes (forming_scene, cone_scene) share besides their named inputs
// (tool_scene_inputs.hpp): the material card of [scene], the checks across keys, the Newton
// options from the [solver] fields, the output options from the [output] fields, and [contact]
// as summary.json shows it.
#include "forward/contact/shell_contact.hpp"
#include "forward/io/toml_reader.hpp"
#include "forward/material/material_card.hpp"
#include "forward/scenes/common/fe_run.hpp"
#include "forward/solver/linear_solver.hpp"
#include "forward/solver/newton_solver.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace spifit::scene {

// [scene] material: the card file relative to the scene file (unless required, default C.3 +
// C.4 of the bundled tree: ../../../materials/aa3003o_c3c4.toml from the scene's folder); a
// missing key (if required), card file or default card fails on the key.
material::MaterialCard read_scene_material(const io::TomlTable& sc, const std::string& scene_path, bool required = false);

// A check across keys that a scene's values fail (empty key: none): the key blamed, its value
// as the file would write it, and why. The reader throws it as an io::InputError; a changed
// input (Scene::check_inputs) reports text().
struct InputViolation {
  std::string key, value, message;
  explicit operator bool() const { return !key.empty(); }
  std::string text() const;  // "key = value: message"; "" for none
};

// [solver] tangent: how a tangent made non-symmetric (by sliding friction or kinematic
// hardening) is factorised. auto: its symmetric part with CHOLMOD while the friction coefficient
// is at most kSymmetrisedTangentFriction, else exact (NewtonOptions::symmetric_tangent; the
// measurements behind the rule are in docs/design/contact.md, "Friction tangent").
enum class FrictionTangent { automatic, exact, symmetrised };
inline constexpr double kSymmetrisedTangentFriction = 0.2;
std::string to_string(FrictionTangent t);
bool friction_tangent_from_string(const std::string& s, FrictionTangent* t);
bool symmetrised_tangent(FrictionTangent t, double friction);

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
  o.estimate_next_correction = s.estimate_next_correction;
  o.stabilisation = s.stabilisation;
  if (s.linear_solver) o.linear_solver = *s.linear_solver;
  o.symmetric_tangent = symmetrised_tangent(s.tangent, s.contact.friction);
  return o;
}

// The Newton keys of [solver] (tool_solver_json).
template <typename Scene>
nlohmann::json tool_newton_json(const Scene& s) {
  return {{"travel_per_increment", s.travel_per_increment},
          {"max_iterations", s.max_iterations},
          {"line_search", s.line_search},
          {"extrapolate", s.extrapolate},
          {"force_tolerance", s.force_tolerance},
          {"displacement_tolerance", s.displacement_tolerance},
          {"estimate_next_correction", s.estimate_next_correction},
          {"divergence_after", s.divergence_after},
          {"stabilisation", s.stabilisation},
          {"tangent", to_string(s.tangent)},
          {"symmetrised_tangent", symmetrised_tangent(s.tangent, s.contact.friction)}};
}

// The check across [solver] and [contact] keys (empty: none): the MST contact needs the
// explicit scheme.
template <typename Scene>
InputViolation scheme_violation(const Scene& s) {
  if (s.contact.method == contact::ContactOptions::Method::mst && !s.explicit_scheme)
    return {"contact.method", "\"mst\"", "the Moving Spherical Tool is a contact of the explicit scheme: set solver.scheme = \"explicit\""};
  return {};
}

// The explicit scheme's options of a tool scene, none for an implicit one.
template <typename Scene>
std::optional<solver::ExplicitOptions> tool_explicit_options(const Scene& s) {
  if (!s.explicit_scheme) return std::nullopt;
  return s.explicit_options;
}

// The [solver] fields of a tool scene as summary.json shows them.
template <typename Scene>
nlohmann::json tool_solver_json(const Scene& s) {
  nlohmann::json j = tool_newton_json(s);
  j["scheme"] = s.explicit_scheme ? "explicit" : "implicit";
  if (s.explicit_scheme) {
    const solver::ExplicitOptions& o = s.explicit_options;
    j["mass_scaling"] = o.mass_scaling;
    j["rotational_mass_scaling"] = o.rotational_scaling;
    j["target_time_step"] = o.target_time_step;
    j["time_scaling"] = o.time_scaling;
    j["damping"] = o.damping;
    j["bulk_viscosity_linear"] = o.bulk_viscosity_linear;
    j["bulk_viscosity_quadratic"] = o.bulk_viscosity_quadratic;
    j["time_step_safety"] = o.safety;
    j["max_steps"] = o.max_steps;
  }
  return j;
}

// The output options of a tool scene (any type with the [output] fields of tool_scene_inputs.hpp).
template <typename Scene>
FeOutputOptions tool_output_options(const Scene& s) {
  FeOutputOptions o;
  o.vtu_every = s.vtu_every;
  o.checkpoint_every = s.checkpoint_every;
  o.checkpoint_increments = s.checkpoint_increments;
  return o;
}

// The [contact] options as summary.json shows them: penalty, friction, points, surface.
nlohmann::json contact_json(const contact::ContactOptions& c);

}  // namespace spifit::scene
