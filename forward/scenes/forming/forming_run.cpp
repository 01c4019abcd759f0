#include "forward/scenes/forming/forming_run.hpp"

#include "forward/mesh/mesh_quality.hpp"
#include "forward/model/hanging_nodes.hpp"
#include "forward/scenes/common/energy_log.hpp"
#include "forward/scenes/common/force_log.hpp"
#include "forward/scenes/common/sensitivity_log.hpp"
#include "forward/scenes/common/scene_tables.hpp"
#include "forward/scenes/common/vtu_log.hpp"
#include "forward/scenes/forming/forming_path.hpp"
#include "forward/scenes/forming/path_section_log.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace spifit::scene {
namespace {

// Edges clamped (translations, and rotations where the nodes have them); a half model's
// symmetry plane y = 0 holds u_y and the rotations about x and z. A coarsened sheet's hanging
// nodes follow their edges' ends (model/hanging_nodes.hpp). Drilling rotations out of the system
// (nodal rotation frames). A solid sheet's sets hold whole node columns (mesh::extrude_sheet).
solver::DofConstraints sheet_constraints(const FormingScene& s, model::FeModel& model) {
  solver::DofConstraints c(model.num_dofs());
  const mesh::Mesh& mesh = model.mesh();
  for (int n : mesh.node_sets.at("boundary"))
    for (int k = 0; k < model.node_dofs(n); ++k) c.prescribe(model.node_dof(n, k));
  if (s.half)
    for (int n : mesh.node_sets.at("symmetry_y0"))
      for (int k : {1, 3, 5})
        if (k < model.node_dofs(n) && !c.prescribed(model.node_dof(n, k))) c.prescribe(model.node_dof(n, k));
  model::tie_hanging_translations(model, &c);
  if (model.family().dofs_per_node() == 6) model.use_nodal_rotation_frames(&c);
  model::tie_hanging_rotations(model, &c);
  c.finalize();
  return c;
}

FeRunSetup forming_setup(const FormingScene& s) {
  FeRunSetup f(forming_centre_path(s));
  f.kind = s.kind;
  f.name = s.name;
  f.input_files = {{"scene", s.file}, {"material card", s.card.file}, {"G-code", s.gcode}};
  f.mesh = forming_sheet_mesh(s);
  f.thickness = s.thickness;
  f.material = s.card.params;
  f.model.shell.thickness_points = s.thickness_points;
  f.model.shell.hourglass_stiffness = s.hourglass_stiffness;
  f.tool_radius = s.radius;
  f.contact = s.contact;
  const double length = f.tool_path.length();
  // Spin [rad per unit load factor] = omega [rad/s] x travel time L / feed [s].
  f.spin_per_load_factor = s.spin * 2.0 * std::numbers::pi / 60.0 * length / s.feed;
  f.load_map = LoadMap::linear(length);
  const double feed = s.feed;
  f.time_of_travel = [feed](double travel) { return travel / feed; };
  f.element = s.element;
  f.layers = s.layers;
  f.hourglass.scale = s.hourglass_scale;
  f.constraints = [&s](model::FeModel& m) { return sheet_constraints(s, m); };
  f.marks = forming_marks(s, f.tool_path);
  f.newton = tool_newton_options(s, length);
  // The increment size starts afresh at every mark, as after a change of direction.
  for (const Mark& m : f.marks)
    if (m.travel < length) f.newton.restarts.push_back(m.travel / length);
  f.output = tool_output_options(s);
  f.explicit_scheme = tool_explicit_options(s);
  f.density = s.card.density;
  f.progress_every_increment = true;
  return f;
}

// A warning (empty: none) when a waypoint of the tool centre at or below the sheet's top
// (tool tip at z <= 0) lies outside the square sheet (|x| or |y| beyond half its side, where the
// edges are clamped): there the tool presses on the clamp, not the part.
std::string path_edge_warning(const toolpath::ToolPath& path, const FormingScene& s) {
  const double length = s.length, top = 0.5 * s.thickness + s.radius;  // centre z with the tip on the top surface
  double worst = 0.0;
  Eigen::Vector3d where = Eigen::Vector3d::Zero();
  for (const toolpath::Waypoint& w : path.waypoints()) {
    if (w.position.z() > top + 1e-9) continue;  // in the air
    const double past = std::max(std::abs(w.position.x()), std::abs(w.position.y())) - 0.5 * length;
    if (past > worst) {
      worst = past;
      where = w.position;
    }
  }
  if (worst <= 0.0) return {};
  char buf[320];
  std::snprintf(buf, sizeof buf, "the tool path runs %.3g mm past the clamped sheet edge (tool centre at x = %.4g, y = %.4g mm; "
                "the sheet spans +-%.4g mm): forces there are the clamp's, not the part's", worst, where.x(), where.y(), 0.5 * length);
  return buf;
}

ForceLogFormat force_format(const FormingScene& s) {
  ForceLogFormat f;
  f.columns = {{"time", "s"}, {"tool_x", "mm"}, {"tool_y", "mm"}, {"tool_z", "mm"}, {"Fx", "N"}, {"Fy", "N"}, {"Fz", "N"},
               {"max_penetration", "mm"}, {"iterations", ""}};
  f.comment = "# spifit " + s.kind + " scene " + s.name + ": force BY the sheet ON the tool; tool = centre position" +
              (s.half ? "; half model, forces mirrored to the full sheet" : "");
  f.row = [](const ToolForceSample& x) {
    return std::vector<double>{x.time, x.centre.x(), x.centre.y(), x.centre.z(), x.force.x(), x.force.y(), x.force.z(), x.penetration,
                               static_cast<double>(x.iterations)};
  };
  // A half model carries half of Fx and Fz, and no Fy.
  if (s.half) f.whole = [](const Eigen::Vector3d& v) { return Eigen::Vector3d(2.0 * v.x(), 0.0, 2.0 * v.z()); };
  return f;
}

nlohmann::json forming_inputs(const FormingScene& s, const model::FeModel& model, double length) {
  nlohmann::json j;
  j["scene"] = s.name;
  j["scene_file"] = s.file;
  j["kind"] = s.kind;
  j["description"] = s.description;
  j["material"] = s.card.name;
  j["model"] = {{"elements", model.num_elements()}, {"nodes", model.num_nodes()}, {"half", s.half},
                {"thickness", s.thickness}, {"length", s.length}, {"thickness_points", s.thickness_points}};
  if (s.hourglass_stiffness > 0.0) j["model"]["hourglass_stiffness"] = s.hourglass_stiffness;
  if (s.element == "brick") {
    j["model"].erase("thickness_points");
    j["model"].update({{"element", s.element}, {"layers", s.layers}, {"hourglass_scale", s.hourglass_scale}});
  }
  if (s.element == "solid_shell") j["model"]["element"] = s.element;
  if (s.coarse_levels > 0)
    j["model"].update({{"coarse_levels", s.coarse_levels}, {"fine_band", s.fine_band}, {"hanging_nodes", model.mesh().constrained_nodes.size()}});
  j["tool"] = {{"radius", s.radius}, {"travel", length}, {"feed", s.feed}, {"spin_rpm", s.spin}, {"gcode", s.gcode}};
  j["contact"] = contact_json(s.contact);
  j["solver"] = tool_solver_json(s);
  j["warnings"] = model.warnings();
  return j;
}

}  // namespace

FormingResult run_forming_scene(const FormingScene& scene, const RunFiles& files, const RunControl& control) {
  FeRun run(forming_setup(scene), files, control);
  const double length = run.setup().load_map.length();
  const ForceLogFormat format = force_format(scene);
  auto& force = run.add_observer(std::make_unique<ForceLog>(format, run.files()));
  const SensitivityLog* sensitivity = nullptr;
  if (!run.sensitivity_names().empty()) {
    sensitivity = &run.add_observer(std::make_unique<SensitivityLog>(
        run.sensitivity_names(), run.sensitivity_units(), run.sensitivity_values(),
        "# spifit " + scene.kind + " scene " + scene.name + ": derivatives of the force BY the sheet ON the tool with respect to the card's parameters (and the contact's penalty and friction) "
        "(direct differentiation), and each scaled by the parameter's value" + (scene.half ? "; half model, mirrored to the full sheet" : ""),
        format.whole, run.files()));
  }
  auto& energy = run.add_observer(std::make_unique<EnergyLog>(
      "# spifit " + scene.kind + " scene " + scene.name + ": energy account of the model after each increment (model::ModelEnergies), N mm; "
      "external work = the tool's work on the sheet (trapezoidal rule; a half model: on the half); " +
      std::string(scene.explicit_scheme ? "explicit: kinetic energy and damping work in their columns; " : "kinetic energy 0 (static implicit); ") +
      "balance_error = external_work - the other columns", run.files(), scene.explicit_scheme));
  auto& sections = run.add_observer(std::make_unique<PathSectionLog>(scene.sections, scene.name, run.files(), run.model().sensitivity_count()));
  run.add_observer(std::make_unique<VtuLog>(run.files(), scene.vtu_every)).set_sensitivities(run.sensitivity_names(), run.sensitivity_values());

  FormingResult r;
  r.inputs = forming_inputs(scene, run.model(), length);
  if (!run.sensitivity_names().empty()) r.inputs["sensitivities"] = run.sensitivity_names();
  r.name = scene.name;
  r.kind = scene.kind;
  r.elements = run.model().num_elements();
  r.path_length = length;
  r.feed = scene.feed;
  r.half = scene.half;
  r.warnings = run.warnings();
  if (const std::string w = path_edge_warning(run.setup().tool_path, scene); !w.empty()) r.warnings.push_back(w);
  r.take(run.run(r.inputs), force, energy, scene.contact, scene.thickness, mesh::median_edge_length(run.setup().mesh));
  r.sections = sections.sections();
  if (sensitivity) r.sensitivities = sensitivity->table();
  files.write("summary.json", r.to_json().dump(2) + "\n");
  return r;
}

}  // namespace spifit::scene
