// Running a cone scene on the FE-run skeleton: mesh, clamp, cyclic ties and virtual tools, the
// contour path as the load, observers (docs/design/cone.md).
#include "forward/scenes/cone/cone_run.hpp"

#include "forward/mesh/mesh_quality.hpp"
#include "forward/model/cyclic_symmetry.hpp"
#include "forward/model/hanging_nodes.hpp"
#include "forward/scenes/common/energy_log.hpp"
#include "forward/scenes/common/force_log.hpp"
#include "forward/scenes/common/scene_tables.hpp"
#include "forward/scenes/common/sensitivity_log.hpp"
#include "forward/scenes/common/vtu_log.hpp"
#include "forward/scenes/cone/cone_contour_log.hpp"
#include "forward/scenes/cone/cone_load_map.hpp"
#include "forward/scenes/cone/cone_observable_log.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

namespace spifit::scene {
namespace {

using json = nlohmann::json;

bool is_pie(const ConeScene& s) { return s.pie_angle < 360.0; }

// The rim's columns of a solid sheet (levels 0 .. L of mesh::extrude_sheet): every node held
// with clamp_rotations; otherwise the mid-surface alone, as the shell's rim without its
// rotations: level k moves opposite to level L - k (u_k = -u_{L-k}, their mean stays put) and a
// middle level is held, so that the column may turn about its middle and change its length.
void clamp_solid_rim(const ConeScene& s, const model::FeModel& model, const std::vector<char>& slave, solver::DofConstraints* c) {
  const int levels = (s.element == "brick" ? s.layers : 1) + 1, n = model.num_nodes() / levels;
  if (n * levels != model.num_nodes())
    throw std::logic_error("cone rim: the model's " + std::to_string(model.num_nodes()) + " nodes are not " + std::to_string(levels) +
                           " levels of a sheet");
  for (int node : model.mesh().node_sets.at("rim")) {
    if (slave[static_cast<std::size_t>(node)]) continue;
    const int k = node / n, mirror = (levels - 1 - k) * n + node % n;
    for (int i = 0; i < 3; ++i) {
      if (s.clamp_rotations || mirror == node) c->prescribe(model.node_dof(node, i));
      else if (k < levels - 1 - k) c->tie(model.node_dof(node, i), {{model.node_dof(mirror, i), -1.0}});
    }
  }
}

// Rim (= clamp radius) fixed in translation (and rotation on request; a solid's columns:
// clamp_solid_rim); pie edges tied cyclically: the DOFs of edge_theta1 are those of edge_theta0
// rotated by gamma, and the axis node moves along z only (tie_cyclic_edges). The rim node of
// edge_theta1 is a tied node: it is not clamped itself but follows its clamped partner on
// edge_theta0 (R 0 = 0). A coarsened centre's hanging nodes follow their edges' ends
// (model/hanging_nodes.hpp; an end on edge_theta1 is expanded through its cyclic tie).
solver::DofConstraints cone_constraints(const ConeScene& s, model::FeModel& model) {
  const mesh::Mesh& m = model.mesh();
  solver::DofConstraints c(model.num_dofs());
  std::vector<char> slave(static_cast<std::size_t>(m.num_nodes()), 0);
  if (is_pie(s)) {
    model::tie_cyclic_edges(model, "edge_theta0", "edge_theta1", s.pie_angle, &c);
    for (int n : m.node_sets.at("edge_theta1")) slave[static_cast<std::size_t>(n)] = 1;
    for (int n : m.node_sets.at("axis")) slave[static_cast<std::size_t>(n)] = 0;
  }
  const bool shell = model.family().dofs_per_node() == 6;
  if (shell) {
    const int clamped = s.clamp_rotations ? 6 : 3;
    for (int n : m.node_sets.at("rim")) {
      if (slave[static_cast<std::size_t>(n)]) continue;
      for (int k = 0; k < clamped; ++k) c.prescribe(model.node_dof(n, k));
    }
  } else {
    clamp_solid_rim(s, model, slave, &c);
  }
  model::tie_hanging_translations(model, &c);
  // Five unknowns at every shell node away from the ties and the clamp: the drilling rotations
  // leave the factorisation (docs/design/numerics-shell.md, "Nodal rotation frames").
  if (shell) model.use_nodal_rotation_frames(&c);
  model::tie_hanging_rotations(model, &c);
  c.finalize();
  return c;
}

// Virtual tools of a pie (thesis Fig. 8.4): copies at +gamma and -gamma (one copy for 180).
std::vector<double> tool_copies(const ConeScene& s) {
  if (!is_pie(s) || !s.virtual_tools) return {};
  if (s.pie_angle == 180.0) return {180.0};
  return {s.pie_angle, -s.pie_angle};
}

std::vector<std::string> scene_warnings(const ConeScene& s, const ConeTrack& track, const FeRun& run) {
  std::vector<std::string> w = run.warnings();
  if (!is_pie(s)) return w;
  if (!s.virtual_tools) w.emplace_back("virtual tools off: a tool footprint crossing a pie edge does not act on the other edge");
  // The copies at +-gamma see the neighbouring pies only: a footprint reaching further (near the
  // axis of a narrow pie) would be missed.
  const double r = track.min_axis_distance();
  const double reach = r * std::sin(std::min(s.pie_angle, 90.0) * std::numbers::pi / 180.0);
  if (s.virtual_tools && s.tool_radius >= reach) {
    char buf[240];
    std::snprintf(buf, sizeof buf, "the tool centre comes within %.3g mm of the axis, where its footprint may reach pies beyond the "
                  "neighbours (the virtual tools are at +-%.4g deg only)", r, s.pie_angle);
    w.emplace_back(buf);
  }
  return w;
}

json summary_head(const ConeScene& s, const model::FeModel& model, const model::ToolContact& tool, const ConeTrack& track,
                  const std::vector<std::string>& warnings) {
  const auto& p = track.path().path;
  json j;
  j["scene"] = s.name;
  j["scene_file"] = s.file;
  j["kind"] = "cone";
  j["description"] = s.description;
  j["material"] = s.card.name;
  j["preset"] = s.preset;
  j["model"] = {{"elements", model.num_elements()},       {"nodes", model.num_nodes()},
                {"pie_angle", s.pie_angle},               {"clamp_radius", s.clamp_radius},
                {"clamp_rotations", s.clamp_rotations},   {"thickness", s.thickness},
                {"thickness_points", s.thickness_points}, {"thickness_rule", element::to_string(s.thickness_rule)},
                {"elements_per_45deg", s.mesh.elements_per_45deg},
                {"material_axes", model::to_string(s.material_axes)},
                {"virtual_tools_deg", tool.copies_deg()}};
  if (s.hourglass_stiffness > 0.0) j["model"]["hourglass_stiffness"] = s.hourglass_stiffness;
  if (s.element == "brick") {
    for (const char* key : {"thickness_points", "thickness_rule"}) j["model"].erase(key);
    j["model"].update({{"element", s.element}, {"layers", s.layers}, {"hourglass_scale", s.hourglass_scale}});
  }
  if (s.element == "solid_shell") j["model"]["element"] = s.element;
  if (s.mesh.coarse_inside > 0.0)
    j["model"].update({{"coarse_inside", s.mesh.coarse_inside}, {"hanging_nodes", model.mesh().constrained_nodes.size()}});
  json stages = json::array();
  for (const auto& o : s.stages)
    stages.push_back({{"wall_angle", o.wall_angle_deg}, {"stepdown", o.stepdown}, {"contours", o.contours}, {"top_radius", o.top_radius}});
  j["path"] = {{"stages", stages}, {"length", p.length()}, {"duration", p.duration()}, {"waypoints", p.waypoints().size()},
               {"contours", track.contours().size()}};
  j["tool"] = {{"radius", s.tool_radius}, {"feed", s.feed}, {"spin_rpm", s.spin}};
  j["contact"] = contact_json(s.contact);
  j["solver"] = tool_solver_json(s);
  j["solver"]["move_increments"] = s.move_increments;
  j["warnings"] = warnings;
  return j;
}

FeRunSetup cone_setup(const ConeScene& scene, const ConeTrack& track) {
  FeRunSetup f(track.path().path);
  f.kind = "cone";
  f.name = scene.name;
  f.input_files = {{"scene", scene.file}, {"material card", scene.card.file}};
  f.mesh = cone_scene_mesh(scene);
  f.thickness = scene.thickness;
  f.material = scene.card.params;
  f.model.shell.thickness_points = scene.thickness_points;
  f.model.shell.hourglass_stiffness = scene.hourglass_stiffness;
  f.model.shell.thickness_rule = scene.thickness_rule;
  f.model.material_axes = scene.material_axes;
  f.tool_radius = scene.tool_radius;
  f.contact = scene.contact;
  f.tool_copies_deg = tool_copies(scene);
  const double length = f.tool_path.length(), duration = f.tool_path.duration();
  ConeLoadMap map = cone_load_map(track.path(), scene.travel_per_increment, scene.move_increments);
  // Spin [rad per unit load factor] = omega [rad/s] x the time per unit load factor where the
  // tool touches (the moves in the air, shortened by the map, turn it faster; no effect there).
  f.spin_per_load_factor = scene.spin * 2.0 * std::numbers::pi / 60.0 * duration * map.map.effective_length() / length;
  f.load_map = map.map;
  f.time_of_travel = [length, duration](double travel) { return travel / length * duration; };
  f.element = scene.element;
  f.layers = scene.layers;
  f.hourglass.scale = scene.hourglass_scale;
  f.constraints = [&scene](model::FeModel& m) { return cone_constraints(scene, m); };
  f.newton = tool_newton_options(scene, map.map.effective_length());
  f.newton.breakpoints = map.breakpoints;
  for (std::size_t k = 0; k < track.contours().size(); ++k) {
    const ContourSpan& c = track.contours()[k];
    f.marks.push_back({c.end, "stage " + std::to_string(c.stage) + " contour " + std::to_string(c.contour), static_cast<int>(k)});
  }
  f.output = tool_output_options(scene);
  f.explicit_scheme = tool_explicit_options(scene);
  f.density = scene.card.density;
  return f;
}

ForceLogFormat force_format(const ConeScene& s, const ConeTrack& track) {
  ForceLogFormat f;
  f.columns = {{"time", "s"}, {"tool_x", "mm"}, {"tool_y", "mm"}, {"tool_z", "mm"}, {"theta", "deg"}, {"Fx", "N"}, {"Fy", "N"},
               {"Fz", "N"}, {"Fr", "N"}, {"Ftheta", "N"}, {"stage", ""}, {"contour", ""}, {"move", ""}, {"max_penetration", "mm"},
               {"iterations", ""}, {"surface_penetration", "mm"}};
  f.comment = "# spifit cone scene " + s.name +
              ": force BY the sheet ON the (real) tool, Cartesian and polar at the tool's polar angle theta; "
              "tool = centre; move: 0 start, 1 approach, 2 contour, 3 ramp, 4 lift, 5 move, 6 plunge, 7 retract, 8 stage_change";
  f.row = [&track](const ToolForceSample& x) {
    const Eigen::Vector3d fp = polar_components(x.force, x.centre);
    const toolpath::ConeSegment& seg = track.segment_at(x.travel);
    const double theta = std::atan2(x.centre.y(), x.centre.x()) * 180.0 / std::numbers::pi;
    return std::vector<double>{x.time, x.centre.x(), x.centre.y(), x.centre.z(), theta, x.force.x(), x.force.y(), x.force.z(), fp.x(),
                               fp.y(), static_cast<double>(seg.stage), static_cast<double>(seg.contour),
                               static_cast<double>(static_cast<int>(seg.move)), x.penetration, static_cast<double>(x.iterations),
                               x.surface_penetration};
  };
  return f;
}

}  // namespace

ConeResult run_cone_scene(const ConeScene& scene, const RunFiles& files, const RunControl& control) {
  const ConeTrack track(cone_scene_path(scene));
  FeRun run(cone_setup(scene, track), files, control);
  auto& force = run.add_observer(std::make_unique<ForceLog>(force_format(scene, track), run.files()));
  const SensitivityLog* sensitivity = nullptr;
  if (!run.sensitivity_names().empty())
    sensitivity = &run.add_observer(std::make_unique<SensitivityLog>(
        run.sensitivity_names(), run.sensitivity_units(), run.sensitivity_values(),
        "# spifit cone scene " + scene.name + ": derivatives of the force BY the sheet ON the (real) tool, Cartesian, with respect to the "
        "card's parameters (and the contact's penalty and friction) (direct differentiation; a pie's virtual tools included), "
        "and each scaled by the parameter's value",
        nullptr, run.files()));
  auto& contours = run.add_observer(std::make_unique<ConeContourLog>(scene.name, track, force, run.files()));
  auto& energy = run.add_observer(std::make_unique<EnergyLog>(
      "# spifit cone scene " + scene.name + ": energy account of the (pie) model after each increment (model::ModelEnergies), N mm; "
      "external work = the tool's and its copies' work on the sheet (trapezoidal rule); " +
      std::string(scene.explicit_scheme ? "explicit: kinetic energy and damping work in their columns; "
                                        : "kinetic energy 0 (static implicit); ") +
      "balance_error = external_work - the other columns", run.files(), scene.explicit_scheme));
  auto& observables = run.add_observer(std::make_unique<ConeObservableLog>(scene, run.model(), run.setup().mesh, track, run.files()));
  run.add_observer(std::make_unique<VtuLog>(run.files(), scene.vtu_every)).set_sensitivities(run.sensitivity_names(), run.sensitivity_values());

  ConeResult r;
  r.warnings = scene_warnings(scene, track, run);
  r.inputs = summary_head(scene, run.model(), run.tool(), track, r.warnings);
  if (!run.sensitivity_names().empty()) r.inputs["sensitivities"] = run.sensitivity_names();
  r.name = scene.name;
  r.elements = run.model().num_elements();
  r.contours_total = static_cast<int>(track.contours().size());
  r.take(run.run(r.inputs), force, energy, scene.contact, scene.thickness, mesh::median_edge_length(run.setup().mesh));
  for (const ForceSample& s : polar_samples(r.force))
    for (int i = 0; i < 3; ++i)
      if (std::abs(s.polar(i)) > std::abs(r.peak_polar(i))) r.peak_polar(i) = s.polar(i);
  r.contours = contours.means();
  if (scene.steady_state) r.steady_state = steady_state(r.contours, scene.steady_state->first, scene.steady_state->second);
  r.sections = observables.sections();
  r.stages = observables.stages();
  r.history = observables.history();
  r.section_profiles = observables.profiles();
  if (sensitivity) r.sensitivities = sensitivity->table();
  if (!observables.centre_depth_sensitivities().empty()) r.centre_depth_sensitivity = observables.centre_depth_sensitivities().back();
  r.observables = observables.summary();
  files.write("summary.json", r.to_json().dump(2) + "\n");
  return r;
}

}  // namespace spifit::scene
