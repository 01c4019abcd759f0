#include "forward/scenes/common/fe_run.hpp"

#include "forward/io/input_error.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/material/sensitivity_seeds.hpp"
#include "forward/scenes/common/fe_run_stepper.hpp"
#include "forward/scenes/common/run_checkpoint.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <stdexcept>
#include <cstdio>

namespace spifit::scene {
using Clock = FeRunClock;

FeRun::FeRun(FeRunSetup setup, RunFiles files, RunControl control)
    : setup_(std::move(setup)), files_(files), control_(std::move(control)) {
  if (control_.newton_tolerance > 0.0) setup_.newton.force_tolerance = setup_.newton.displacement_tolerance = control_.newton_tolerance;
  if (setup_.explicit_scheme) {
    if (setup_.element != "shell")
      throw std::invalid_argument("the explicit scheme has shell elements only, not " + setup_.element + " elements");
    setup_.model.shell.layer_tangents = false;  // no tangent is assembled
  }
  model::SheetModelSpec spec;
  spec.element = setup_.element;
  spec.layers = setup_.layers;
  spec.shell = setup_.model;
  spec.hourglass = setup_.hourglass;
  // Runs converged further than the scene says converge the solid-shells' enhanced strains
  // further too: at their own 1e-8 the committed states carry errors of that order, which central
  // differences of the derivative checker see (docs/design/sensitivities.md, "Solids").
  if (control_.newton_tolerance > 0.0) spec.enhanced_tolerance = std::min(spec.enhanced_tolerance, 1e-3 * control_.newton_tolerance);
  model_ = model::make_sheet_model(setup_.mesh, setup_.thickness, setup_.material, spec, &solid_);
  const toolpath::ToolPath& path = setup_.tool_path;
  const LoadMap& map = setup_.load_map;
  tool_ = &model_->add_contribution(std::make_unique<model::ToolContact>(
      model_->mesh(), model_->family().contact_surface(), setup_.tool_radius,
      [&path, &map](double lambda) { return path.at_distance(map.travel(lambda)); }, setup_.contact, setup_.spin_per_load_factor));
  if (!setup_.tool_copies_deg.empty()) tool_->set_copies(setup_.tool_copies_deg);
  constraints_ = std::make_unique<solver::DofConstraints>(setup_.constraints(*model_));
  solver_ = std::make_unique<solver::NewtonSolver>(*model_, *constraints_, setup_.newton);
  if (!control_.sensitivities.empty()) enable_sensitivities();
}

bool is_contact_sensitivity(const std::string& name) { return name == kPenaltySensitivity || name == kFrictionSensitivity; }

std::vector<std::string> card_sensitivity_names(const std::vector<std::string>& names) {
  std::vector<std::string> out = names;
  for (const char* contact : {kPenaltySensitivity, kFrictionSensitivity}) {
    int count = 0;
    for (std::string& n : out)
      if (n == contact) {
        n.clear();
        ++count;
      }
    if (count > 1) throw std::invalid_argument(std::string(contact) + " is named twice");
  }
  return out;
}

// Refusals name the scene file, the option and its value.
void FeRun::enable_sensitivities() {
  std::string file, names;
  for (const auto& [role, path] : setup_.input_files)
    if (role == "scene") file = path;
  for (const std::string& n : control_.sensitivities) names += (names.empty() ? "" : ",") + n;
  auto refuse = [&](const std::string& why) { throw io::InputError(file, "--sensitivities", names, why); };
  if (setup_.explicit_scheme) refuse("the explicit scheme has no exact sensitivities; run the implicit scheme, or differentiate by central differences (a sweep)");
  try {
    const std::vector<material::FieldSeed> seeds = material::sensitivity_seeds(setup_.material, card_sensitivity_names(control_.sensitivities), control_.sensitivity_h_follows_g);
    contact::ShellContact::ParameterSlots slots;
    for (std::size_t k = 0; k < control_.sensitivities.size(); ++k) {
      if (control_.sensitivities[k] == kPenaltySensitivity) slots.penalty = static_cast<int>(k);
      if (control_.sensitivities[k] == kFrictionSensitivity) slots.friction = static_cast<int>(k);
    }
    tool_->set_parameter_slots(slots);
    model_->enable_sensitivities(seeds, static_cast<int>(control_.sensitivities.size()), setup_.material);
  } catch (const std::invalid_argument& e) {
    refuse(e.what());
  }
  // Newton ties a hanging node's rotation increments in frames that turn with the directors; the
  // direct differentiation takes the tie as fixed at the converged state (docs/design/sensitivities.md).
  if (!model_->mesh().constrained_nodes.empty() && model_->family().dofs_per_node() == 6)
    sensitivity_warning_ = "sensitivities of a coarsened sheet: its " + std::to_string(model_->mesh().constrained_nodes.size()) +
                           " hanging nodes' rotation ties turn with the sheet, which the exact derivatives take as fixed; measured up to "
                           "1.4e-4 (a coarsened line) and 1.5e-3 (a coarsened cone) of their largest value off central differences";
}

std::vector<std::string> FeRun::warnings() const {
  std::vector<std::string> w = model_->warnings();
  if (!sensitivity_warning_.empty()) w.push_back(sensitivity_warning_);
  return w;
}

std::vector<double> FeRun::sensitivity_values() const {
  std::vector<double> v;
  for (const std::string& n : control_.sensitivities)
    v.push_back(n == kPenaltySensitivity    ? setup_.contact.penalty
                : n == kFrictionSensitivity ? setup_.contact.friction
                                            : material::material_field(setup_.material, material::find_material_input(n)->field));
  return v;
}

std::vector<std::string> FeRun::sensitivity_units() const {
  std::vector<std::string> units;
  for (const std::string& n : control_.sensitivities)
    units.push_back(n == kPenaltySensitivity ? "N/mm^3" : n == kFrictionSensitivity ? "" : material::find_material_input(n)->info.unit);
  return units;
}

FeRun::~FeRun() = default;

FeRunOutcome FeRun::run(const nlohmann::json& head) {
  if (control_.build_only) {
    FeRunOutcome out;
    out.status = RunStatus::stopped;
    out.message = "built only (RunControl::build_only)";
    return out;
  }
  if (setup_.explicit_scheme) return run_explicit(head);
  auto t0 = Clock::now();
  // The input files' contents go into checkpoints (and are compared on resume): read only when
  // the run writes files; a sweep or fit point runs from the parsed scene alone.
  RunInputs inputs = files_.enabled() ? read_run_inputs(setup_.kind, setup_.input_files) : RunInputs{};
  if (files_.enabled() && !control_.sensitivities.empty()) inputs.files.push_back(sensitivity_input(control_.sensitivities));
  RunLog restored;
  if (control_.resume) {
    // The checkpoint is read (and refused with an InputError) before any output is touched.
    if (!files_.enabled()) throw std::logic_error("FeRun: a resume needs an output directory");
    solver::NewtonState newton;
    read_run_checkpoint(*files_.directory(), inputs, model_.get(), &newton, nullptr, &restored, observers_);
    solver_->set_state(newton);
    t0 -= std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(restored.wall_seconds));
  }
  RunHeartbeat heartbeat(files_, head, control_.heartbeat_seconds);
  heartbeat.write();
  Stepper step(*this, inputs, t0, heartbeat);
  step.start_from(restored);
  step.checkpoints.every_marks = setup_.output.checkpoint_every;
  step.checkpoints.every_increments = setup_.output.checkpoint_increments;
  if (control_.resume)
    for (auto& o : observers_) o->write(WriteReason::end);  // the rows a killed run wrote after its checkpoint are dropped
  else
    for (auto& o : observers_) o->at_start(*model_);

  auto callback = [&step](const solver::IncrementReport& ir) { return step(ir); };
  const solver::NewtonSummary r = control_.resume ? solver_->resume(1.0, callback) : solver_->solve(0.0, 1.0, callback);

  FeRunOutcome out = step.finish(r.converged, r.lambda, r.message, control_.resume ? restored.marks_reached : -1);
  out.counters = r.counters;
  if (!control_.sensitivities.empty()) {
    const solver::NewtonSolver::SensitivitySolveStats& s = solver_->sensitivity_stats();
    out.sensitivity_solves = {{"increments", s.increments},
                              {"gmres_solves", s.gmres_solves},
                              {"gmres_iterations", s.gmres_iterations},
                              {"factorisations", s.factorisations},
                              {"seconds", s.solve_seconds}};
  }
  return out;
}

}  // namespace spifit::scene
