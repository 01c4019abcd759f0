#pragma once
// Shell FE forming scenes with the spherical tool: `indent` (the small clamped square of thesis
// §7.1, for the penalty study), `indent_line` (the line-test sheet of thesis §4.1.1 and §7.2
// indented to 5 mm: point B, the indent test of the identification, §2.3.3) and `line`
// (A -> B -> C -> D -> E). Every geometric input is in the scene file; the defaults are the
// thesis's (schema: docs/reference/file-formats.md). The run is forming_run.hpp.
#include "forward/contact/shell_contact.hpp"
#include "forward/material/material_card.hpp"
#include "forward/mesh/mesh.hpp"
#include "forward/scenes/common/scene_tables.hpp"
#include "forward/scenes/common/sheet_tool_checks.hpp"
#include "forward/solver/explicit_options.hpp"
#include "forward/solver/newton_solver.hpp"

#include <optional>
#include <string>
#include <vector>

namespace spifit::scene {

struct PathPoint {
  std::string name;           // e.g. "B"; sections can be requested at named points
  Eigen::Vector3d tip;        // tool tip (lowest point) [mm]; z relative to the sheet's initial top surface
};

struct FormingScene {
  std::string kind;           // indent, indent_line, line
  std::string name, description, file;
  material::MaterialCard card;
  // Sheet: square of side `length` centred on the origin, clamped on its edges; `half` keeps
  // y >= 0 with symmetry conditions on y = 0.
  double length = 10.0, thickness = 0.3;
  int elements = 10;          // across the full side
  bool half = false;
  double grading = 1.0;
  // Coarsening away from the tool path (mesh::square_sheet): cells farther than fine_band [mm]
  // from the tool tip's path (its pieces below the sheet's top) merge into blocks of up to
  // 2^coarse_levels x 2^coarse_levels cells. 0: the regular mesh.
  int coarse_levels = 0;
  double fine_band = 20.0;
  int thickness_points = 5;
  // The sheet's elements (model::sheet_element_names()): "shell" on the mid-surface, "brick" on
  // the solid sheet in `layers` layers (0 until read: the brick's default, kDefaultBrickLayers), or
  // "solid_shell", one through the thickness with thickness_points along it.
  std::string element = "shell";
  int layers = 0;
  // The bricks' hourglass stabilisation: factor on its stiffness (element::HourglassOptions).
  double hourglass_scale = 1.0;
  // > 0: each element carries its layers at its centre only, with this fraction of the elastic
  // section stiffness on the strains' variation over it (element::ShellOptions). 0: 2 x 2 points.
  double hourglass_stiffness = 0.0;
  // Tool.
  double radius = 5.0;
  double feed = 2.0;          // mm/s (force.csv time = travel / feed)
  double spin = 0.0;          // tool rotation [rev/min] about +z (counter-clockwise seen from above); acts through friction
  std::vector<PathPoint> path;
  std::string gcode;          // G-code file of the tool tip (replaces `path` when set)
  contact::ContactOptions contact;
  // Solver: increments of tool travel.
  double travel_per_increment = 0.1;  // mm
  int max_iterations = 25;
  bool extrapolate = true;            // predictor from the previous increment (NewtonOptions)
  bool line_search = false;           // energy line search (NewtonOptions)
  // Relative (NewtonOptions). 1e-5 changed the indent_line peak force by 1e-12 relative and
  // saved 13 % of the iterations against 1e-7 (docs/design/decisions.md).
  double force_tolerance = 1e-5, displacement_tolerance = 1e-5;
  int divergence_after = solver::NewtonOptions{}.divergence_after;  // the solver's 3
  bool estimate_next_correction = false;  // NewtonOptions; the measured trade: docs/design/decisions.md, "Estimated next correction"
  double stabilisation = 0.0;             // NewtonOptions: damping of an increment failing at the minimum increment
  std::optional<solver::LinearSolverKind> linear_solver;
  FrictionTangent tangent = FrictionTangent::automatic;  // [solver] tangent (scene_tables.hpp)
  // [solver] scheme = "explicit" and its keys (tool_scene_inputs.hpp, add_explicit_inputs).
  bool explicit_scheme = false;
  solver::ExplicitOptions explicit_options;
  // Output.
  int vtu_every = 0;
  std::vector<std::string> sections;  // path point names where the y = 0 section is written
  // Checkpoints (DIR/checkpoint/state.bin, --resume): after every checkpoint_every named points
  // (G-code: corners) and every checkpoint_increments increments, but not at the end of the
  // path; 0: none of that kind. line_half writes 5.5 MB per checkpoint in about 20 ms
  // (docs/design/architecture.md, "Checkpoints and resume").
  int checkpoint_every = 1;
  int checkpoint_increments = 50;
};

// Throws io::InputError naming file, key and value (also for a path that never reaches the
// sheet or a tool that starts inside it).
FormingScene read_forming_scene(const std::string& path);
bool is_forming_kind(const std::string& kind);
// The first check across keys the scene fails (the reader's, and a sweep's after a change): a
// half model's even element count; a tool path ("path": [[path]] or the kind's default, or
// "tool.gcode") that starts outside the sheet and goes below its top surface over it. None: an
// empty violation.
// Also the sheet's thickness over its shortest element edge against the shell's limit
// (model::ShellModelOptions: t/l <= 3), on "sheet.thickness" with the mesh keys in the message.
InputViolation forming_scene_error(const FormingScene& scene);
// The sheet and tool of the scene, for the plausibility checks (sheet_tool_checks.hpp).
SheetAndTool forming_sheet_and_tool(const FormingScene& scene);
// The sheet's mesh (sheet.length, elements, half, grading, coarse_levels, fine_band); std::invalid_argument on
// meaningless values.
mesh::Mesh forming_sheet_mesh(const FormingScene& scene);

}  // namespace spifit::scene
