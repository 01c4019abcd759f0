#pragma once
// The `cone` scene (thesis §4.1.2, §8, §9; docs/design/cone.md): a circular sheet or a pie of
// angle gamma clamped at the clamp radius, formed by the contour tool path of a cone
// (forward/toolpath/cone_path.hpp: presets cone50, cone70, vwall). Pies carry the cyclic ties
// of their edges (model/cyclic_symmetry.hpp) and the virtual tools (the tool's copies rotated
// by +-gamma, ToolContact::set_copies). The run is cone_run.hpp.
#include "forward/contact/shell_contact.hpp"
#include "forward/element/thickness_rule.hpp"
#include "forward/material/material_card.hpp"
#include "forward/mesh/disc_mesh.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/scenes/common/scene_tables.hpp"
#include "forward/scenes/common/sheet_tool_checks.hpp"
#include "forward/scenes/cone/cone_observables.hpp"
#include "forward/solver/explicit_options.hpp"
#include "forward/solver/newton_solver.hpp"
#include "forward/toolpath/cone_path.hpp"

#include <optional>
#include <string>
#include <vector>

namespace spifit::scene {

struct ConeScene {
  std::string name, description, file;
  material::MaterialCard card;
  std::string preset;  // cone50, cone70, vwall; empty: geometry given in [cone]
  // One cone (cone50, cone70, explicit geometry) or the vwall stages: their geometry. The sheet
  // thickness, tool radius, feed and pie angle below are the path's (cone_scene_stages).
  std::vector<toolpath::ConePathOptions> stages;
  double pie_angle = 360.0;        // gamma [deg]; 360 / gamma an integer
  // Sheet: the mesh is a disc or pie of radius clamp_radius (its rim is the clamp).
  double thickness = 1.2;
  double clamp_radius = 91.5;      // default: top radius + 1.5 mm (an assumption: docs/design/cone.md)
  bool clamp_rotations = false;    // thesis: translations only
  mesh::DiscOptions mesh;          // radius and angle follow clamp_radius and pie_angle
  int thickness_points = 5;
  // The sheet's elements (model::sheet_element_names()): "shell", "brick" in `layers` layers (0
  // until read: kDefaultBrickLayers) or "solid_shell"; the bricks' hourglass_scale. A solid rim
  // is clamped column by column: clamp_rotations holds every node of it, otherwise its
  // mid-surface alone is held (cone_run.cpp).
  std::string element = "shell";
  int layers = 0;
  double hourglass_scale = 1.0;
  // > 0: each element carries its layers at its centre only, with this fraction of the elastic
  // section stiffness on the strains' variation over it (element::ShellOptions). 0: 2 x 2 points.
  double hourglass_stiffness = 0.0;
  // [sheet] material_axes: "fixed" (default; rolling direction = x everywhere, a rolled sheet) or
  // "polar" (rolling direction = the radial direction of each element: the same material in every
  // pie, as the cyclic ties of a pie assume; docs/design/cone.md, "Material axes").
  model::ShellModelOptions::MaterialAxes material_axes = model::ShellModelOptions::MaterialAxes::fixed;
  // Gauss (default) or "surface" (Simpson per half, with the surface points: integrates the
  // fully plastic moment exactly; 5 Gauss points miss 5.5 % of it, docs/design/numerics-shell.md).
  element::ThicknessRuleKind thickness_rule = element::ThicknessRuleKind::gauss;
  // Tool.
  double tool_radius = 5.0;
  double feed = 2000.0 / 60.0;     // mm/s
  double spin = 0.0;               // rev/min about +z (counter-clockwise seen from above)
  contact::ContactOptions contact;
  bool virtual_tools = true;       // pies: copies of the tool at +-gamma (thesis Fig. 8.4)
  // Solver: increments of tool travel.
  double travel_per_increment = 1.0;  // mm
  // Increments per horizontal move between pie contours (tool in the air; cone_load_map.hpp);
  // 0: one per travel_per_increment like the rest of the path.
  int move_increments = 1;
  int max_iterations = 25;
  bool extrapolate = true;
  // Energy line search on by default for cones: on cone70_pie45_short it cut the Newton
  // iterations 1692 -> 1236 and the cut-backs 45 -> 6, forces within 1.3 % on the loaded
  // contours (docs/design/cone.md).
  bool line_search = true;
  double force_tolerance = 1e-5, displacement_tolerance = 1e-5;
  // NewtonOptions::divergence_after. 10 saves 23 % on the fine cone70 (most increments cut back
  // by the 3-iteration rule converge in 8-13 iterations when let run, and each cut-back costs
  // about five smaller increments), but the vwall pie then failed in contour 149 at a tied-edge
  // node: the solver's 3 by default, cone70_pie45_fine.toml sets 10 (docs/design/decisions.md).
  int divergence_after = solver::NewtonOptions{}.divergence_after;
  // NewtonOptions::estimate_next_correction: about 10 % fewer iterations, off by default
  // (docs/design/decisions.md: the vwall run then failed in its last contour).
  bool estimate_next_correction = false;
  // NewtonOptions::stabilisation: damping factor of the viscous forces of an increment that
  // failed at the minimum increment (where the run would end); up to 100 x it if needed. Off by
  // default: on the vwall pie's contour 149 the damped state crept away under a standing tool
  // and the run ended all the same (docs/design/cone.md); 1e-4 is the factor tried there.
  double stabilisation = 0.0;
  std::optional<solver::LinearSolverKind> linear_solver;
  FrictionTangent tangent = FrictionTangent::automatic;  // [solver] tangent (scene_tables.hpp)
  // [solver] scheme = "explicit" and its keys (tool_scene_inputs.hpp, add_explicit_inputs).
  bool explicit_scheme = false;
  solver::ExplicitOptions explicit_options;
  // Output.
  int vtu_every = 0;
  int checkpoint_every = 1;  // completed contours between checkpoints (DIR/checkpoint/state.bin); 0: none
  int checkpoint_increments = 0;  // increments between checkpoints besides; 0: none
  // [output] history_element = { r = 75.55, theta = 22.5 }: the element of the initial mesh whose
  // centroid is nearest to this point writes DIR/history.csv (element_history.hpp; thesis §9.4;
  // shells only).
  struct HistoryPoint {
    double r = 0.0, theta_deg = 0.0;
  };
  std::optional<HistoryPoint> history_element;
  // [output] steady_state = [from, to]: contour range of the steady-state means in summary.json
  // (1-based; thesis §9.3: [60, 80] of the 100-contour cone70). Empty: none.
  std::optional<std::pair<int, int>> steady_state;
};

bool is_cone_kind(const std::string& kind);
// Throws io::InputError naming file, key and value (unknown preset, pie angle not dividing
// 360, clamp radius not beyond the top radius, invalid path geometry, ...).
ConeScene read_cone_scene(const std::string& path);
// The first check across keys the scene fails (the reader's, and a sweep's after a change):
// the surface rule's odd thickness_points, clamp radius beyond the top radius, core and ring
// inside the clamp, each stage's path options, a mesh whose thickness over element length is
// <= 3. None: an empty violation.
InputViolation cone_scene_error(const ConeScene& scene);
// The sheet and tool of the scene, for the plausibility checks (sheet_tool_checks.hpp).
SheetAndTool cone_sheet_and_tool(const ConeScene& scene);

// The stages with the scene's thickness, tool radius, feed and pie angle.
std::vector<toolpath::ConePathOptions> cone_scene_stages(const ConeScene& scene);
// The contours of the scene's path, all stages (1-based contour numbers run up to it).
int cone_scene_contours(const ConeScene& scene);
// The tool path of the scene (tool CENTRE waypoints with their move kind and contour).
toolpath::ConePath cone_scene_path(const ConeScene& scene);
// The mesh of the scene: disc or pie of radius clamp_radius.
mesh::Mesh cone_scene_mesh(const ConeScene& scene);

}  // namespace spifit::scene
