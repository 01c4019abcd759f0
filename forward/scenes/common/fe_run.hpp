#pragma once
// One skeleton for every FE forming run (indent, indent_line, line, cone): the scene kind
// supplies the mesh, the constraints, the tool and its path (with the load map between the load
// factor and the tool's travel), the solver options, the marks (named points of the path) and
// its observers; FeRun builds the shell model with the tool as a contribution, steps the Newton
// solver over the whole path, calls the observers after every increment and at every mark,
// writes VTU steps and checkpoints, and resumes from a checkpoint bit for bit
// (docs/design/architecture.md, "FE runs").
#include "forward/contact/shell_contact.hpp"
#include "forward/material/material_params.hpp"
#include "forward/mesh/mesh.hpp"
#include "forward/model/sheet_model.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/model/tool_contact.hpp"
#include "forward/scenes/common/load_map.hpp"
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/run_heartbeat.hpp"
#include "forward/scenes/common/run_observer.hpp"
#include "forward/scenes/common/run_status.hpp"
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/explicit_options.hpp"
#include "forward/solver/newton_solver.hpp"
#include "forward/toolpath/tool_path.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace spifit::scene {

struct FeOutputOptions {
  int vtu_every = 0;              // increments between VTU steps (0: the initial and final states only)
  int checkpoint_every = 0;       // marks between checkpoints (0: none at marks)
  int checkpoint_increments = 0;  // increments between checkpoints (0: none by count)
};

struct FeRunSetup {
  explicit FeRunSetup(toolpath::ToolPath path) : tool_path(std::move(path)) {}
  std::string kind, name;
  // Files whose contents identify the run, (role, path): ("scene", ...), ("material card", ...),
  // ("G-code", ...). A checkpoint keeps their contents, and a resume with others is refused.
  std::vector<std::pair<std::string, std::string>> input_files;
  mesh::Mesh mesh;  // the sheet's mid-surface
  double thickness = 0.0;
  material::MaterialParams<double> material;
  model::ShellModelOptions model;  // the shell's options; its material axes serve every family
  // The sheet's elements (model::sheet_element_names()), layers of solids through the thickness
  // on the sheet extruded from `mesh`, and the brick's stabilisation.
  std::string element = "shell";
  int layers = 1;
  element::HourglassOptions hourglass;
  // The tool: a sphere whose centre follows tool_path at load_map.travel(lambda) mm.
  toolpath::ToolPath tool_path;
  double tool_radius = 5.0;
  contact::ContactOptions contact;
  std::vector<double> tool_copies_deg;  // virtual tools of a pie (ToolContact::set_copies)
  double spin_per_load_factor = 0.0;    // rad per unit load factor
  LoadMap load_map;
  std::function<double(double travel)> time_of_travel;  // s
  // Supports and ties on the model's DOFs, finalised (the model's rotation frames set in it).
  std::function<solver::DofConstraints(model::FeModel&)> constraints;
  solver::NewtonOptions newton;
  // The explicit scheme instead of the Newton solver (fe_run_explicit.cpp): its options, and the
  // sheet's density [t/mm^3]. Output points every newton.initial_increment of the load factor
  // and at the marks; checkpoints at output points (explicit_dynamics.hpp).
  std::optional<solver::ExplicitOptions> explicit_scheme;
  double density = 2.7e-9;
  std::vector<Mark> marks;  // by increasing travel
  FeOutputOptions output;
  bool progress_every_increment = false;  // a progress line per increment (else marks only)
};

// Besides the card's parameters, a run differentiates with respect to the tool contact's penalty
// K_p and its friction coefficient mu under these names (RunControl::sensitivities).
inline constexpr const char* kPenaltySensitivity = "contact.penalty";
inline constexpr const char* kFrictionSensitivity = "contact.friction";
bool is_contact_sensitivity(const std::string& name);
// The names with the contact's blanked: what material::sensitivity_seeds takes;
// std::invalid_argument when one is named twice.
std::vector<std::string> card_sensitivity_names(const std::vector<std::string>& names);

struct RunControl {
  ProgressSink progress;  // may be empty
  // Continue from DIR/checkpoint/state.bin: the outputs written after the checkpoint are
  // replaced; io::InputError naming the file when there is none, or it is of another version,
  // scene, card or kind, or damaged. Checked before any output is touched.
  bool resume = false;
  // Tests: stop (as a kill would, status "stopped") once this many marks are reached (after
  // their checkpoint), or after this many increments in all (0: run to the end).
  int stop_after_marks = 0;
  int stop_after_increments = 0;
  // End the run (status timed_out) once its wall time passes this many seconds, checked after
  // every increment (0: no limit).
  double time_limit_seconds = 0.0;
  // A signal number set by a SIGINT/SIGTERM handler (0: none): the run ends at the end of the
  // increment under way (status interrupted) after a checkpoint (when it writes files and is
  // not at the end of its path), so that a resume continues it. Checked after every increment.
  const std::atomic<int>* interrupt = nullptr;
  // Seconds between heartbeats of the running summary.json (run_heartbeat.hpp).
  double heartbeat_seconds = kHeartbeatSeconds;
  // Material parameters ("swift.K"), kPenaltySensitivity and kFrictionSensitivity to differentiate the run with
  // respect to, by direct differentiation (docs/design/sensitivities.md): implicit runs only, not
  // resumed.
  std::vector<std::string> sensitivities;
  // With sensitivities: hill.G also moves H = 2 - G (a fit with normalise_hill).
  bool sensitivity_h_follows_g = false;
  // > 0: the implicit solver's force and displacement tolerances instead of the scene's (the
  // derivative checker's runs, so that central differences see the model, not the tolerance),
  // and a thousandth of it the solid-shells' enhanced strains' where that is tighter.
  double newton_tolerance = 0.0;
  // Build the model (its refusals included) and stop before the first increment (status
  // stopped): what sensitivity_refusal.hpp asks before a fit relies on a scene's sensitivities.
  bool build_only = false;
};

struct CheckpointRecord {
  int every_marks = 0, every_increments = 0, written = 0;
  std::size_t bytes = 0;
  double write_seconds = 0.0;
};

// What the skeleton knows of a run's end, common to every FE scene's typed result.
struct FeRunOutcome {
  RunStatus status = RunStatus::running;
  std::string message;  // failed: where and why; stopped, interrupted: after what
  solver::NewtonCounters counters;
  double travel_reached = 0.0;
  int marks_reached = 0;
  std::vector<double> mark_wall_seconds;  // wall time when each mark was reached
  int resumed_at_mark = -1;               // marks reached at the checkpoint a resumed run started from
  CheckpointRecord checkpoints;
  double wall_seconds = 0.0;
  // Explicit runs: steps, time step, mass scaling and what it added, the time-step bound's
  // element (summary.json "explicit"); null for implicit runs.
  nlohmann::json dynamics;
  // Runs with sensitivities: how their solves went (summary.json "sensitivity_solves"); else null.
  nlohmann::json sensitivity_solves;
  bool ok() const { return status == RunStatus::ok; }
};

class FeRun {
 public:
  // Builds the model (std::invalid_argument for a mesh the family rejects, or the explicit scheme
  // with another family than the shell), the tool and the constraints. files: where outputs go
  // (none: a run in memory).
  FeRun(FeRunSetup setup, RunFiles files, RunControl control);
  FeRun(const FeRun&) = delete;
  FeRun& operator=(const FeRun&) = delete;
  ~FeRun();

  const FeRunSetup& setup() const { return setup_; }
  const RunFiles& files() const { return files_; }
  model::FeModel& model() { return *model_; }
  // The model as a shell model; null for other families.
  model::ShellModel* shell_model() { return dynamic_cast<model::ShellModel*>(model_.get()); }
  const model::ToolContact& tool() const { return *tool_; }
  // The material parameters the run differentiates with respect to (RunControl::sensitivities)
  // and their values and units (sensitivities.csv's columns).
  const std::vector<std::string>& sensitivity_names() const { return control_.sensitivities; }
  std::vector<double> sensitivity_values() const;
  std::vector<std::string> sensitivity_units() const;
  // The model's warnings, and what the run's sensitivities cannot follow exactly.
  std::vector<std::string> warnings() const;

  // Observers are called in the order added; add them all before run().
  template <typename O>
  O& add_observer(std::unique_ptr<O> o) {
    O& ref = *o;
    observers_.push_back(std::move(o));
    return ref;
  }

  // Runs the whole path (or resumes it). head: the summary's description of the inputs, written
  // as DIR/summary.json with status "running" (and pid, host, started, heartbeat) before the
  // first increment, its heartbeat and "progress" rewritten every RunControl::heartbeat_seconds as
  // increments complete. The final summary is the caller's to write, from its typed result.
  FeRunOutcome run(const nlohmann::json& head);

 private:
  FeRunSetup setup_;
  RunFiles files_;
  RunControl control_;
  mesh::Mesh solid_;  // the solid sheet of a solid family (model_ refers to it)
  std::unique_ptr<model::FeModel> model_;
  model::ToolContact* tool_ = nullptr;
  std::unique_ptr<solver::DofConstraints> constraints_;
  std::unique_ptr<solver::NewtonSolver> solver_;
  std::vector<std::unique_ptr<RunObserver>> observers_;
  std::string sensitivity_warning_;
  class Stepper;  // the per-increment bookkeeping (fe_run_stepper.hpp)
  FeRunOutcome run_explicit(const nlohmann::json& head);
  void enable_sensitivities();
};

}  // namespace spifit::scene
