// FeRun with the explicit scheme (docs/design/explicit.md): the same model, tool, constraints,
// marks and observers as an implicit run; solver::ExplicitSolver steps the load factor in time,
// and the observers see the state at every output point (every newton.initial_increment of the
// load factor, and the marks) with the tool force averaged over the interval. Checkpoints are
// written at output points only, where the force filter has just been reset, so that its state
// need not be saved.
#include "forward/io/input_error.hpp"
#include "forward/model/model_energies.hpp"
#include "forward/scenes/common/explicit_dynamics.hpp"
#include "forward/scenes/common/fe_run.hpp"
#include "forward/scenes/common/fe_run_stepper.hpp"

#include <cstdio>
#include <string>

namespace spifit::scene {
namespace {

std::string scene_file(const FeRunSetup& s) {
  for (const auto& [role, path] : s.input_files)
    if (role == "scene") return path;
  return s.name;
}

// The tool force of an output interval, filtered: a least-squares line through the force after
// every step (weighted by the step), taken at the interval's end. It averages out the ringing
// of the sheet as a mean over the interval would, without the mean's lag of half an interval
// behind a growing force (2 % of the indent force at 0.05 mm per interval, measured).
class IntervalForceFit {
 public:
  void add(double dt, const Eigen::Vector3d& f) {
    t_ += dt;
    s0_ += dt;
    s1_ += dt * t_;
    s2_ += dt * t_ * t_;
    f0_ += dt * f;
    f1_ += (dt * t_) * f;
  }
  // The line at the interval's end; `last` (the force after the last step) when there are too
  // few steps to fit a line.
  Eigen::Vector3d at_end(const Eigen::Vector3d& last) const {
    const double det = s0_ * s2_ - s1_ * s1_;
    if (!(det > 1e-12 * s0_ * s2_)) return last;
    const Eigen::Vector3d slope = (s0_ * f1_ - s1_ * f0_) / det;
    const Eigen::Vector3d value0 = (f0_ - s1_ * slope) / s0_;
    return value0 + t_ * slope;
  }

 private:
  double t_ = 0.0, s0_ = 0.0, s1_ = 0.0, s2_ = 0.0;
  Eigen::Vector3d f0_ = Eigen::Vector3d::Zero(), f1_ = Eigen::Vector3d::Zero();
};

// summary.json "explicit" (docs/reference/outputs.md).
nlohmann::json dynamics_json(const solver::ExplicitSummary& r, const solver::ExplicitOptions& o, const model::ExplicitMass& mass, double duration,
                             double kinetic_ratio, const DynamicsView& view, const model::MovingSphereContact* mst, const std::string& smallest) {
  nlohmann::json j = {{"steps", r.steps},
                      {"cut_steps", r.cut_steps},
                      {"simulated_seconds", r.time},
                      {"duration", duration},
                      {"time_step", {{"start", mass.time_step}, {"min", r.min_step}, {"max", r.max_step}}},
                      {"mass_scaling", o.mass_scaling},
                      {"rotational_mass_scaling", o.rotational_scaling},
                      {"target_time_step", o.target_time_step},
                      {"time_scaling", o.time_scaling},
                      {"damping", o.damping},
                      {"bulk_viscosity", {{"linear", o.bulk_viscosity_linear}, {"quadratic", o.bulk_viscosity_quadratic}}},
                      {"time_step_safety", o.safety},
                      {"mass", mass.mass},
                      {"added_mass", mass.added_mass},
                      {"selectively_scaled_elements", mass.scaled_elements},
                      {"smallest_step_element", smallest},
                      {"smallest_unscaled_step", mass.smallest_unscaled_step},
                      {"kinetic", view.kinetic},
                      {"max_kinetic_over_internal", kinetic_ratio},
                      {"damping_work", view.damping_work},
                      {"force_filter", "least-squares line through each output interval's steps, taken at the interval's end"},
                      {"contact", mst ? "mst" : "penalty"}};
  if (mst) {
    const model::MstStatistics& m = mst->statistics();
    j["mst"] = {{"solves", m.solves},
                {"sweeps", m.sweeps},
                {"unconverged_solves", m.unconverged},
                {"max_points", m.max_points},
                {"max_penetration", m.max_penetration},
                {"max_friction_over_mu_normal", m.max_friction_ratio},
                {"work_on_sheet", m.work}};
  }
  return j;
}

// Refuses (io::InputError on the scene's mass_scaling) a run whose stable step needs more than
// max_steps steps, naming the element that sets the step and the mass scaling that would fit.
void check_step_count(const FeRunSetup& setup, const model::ShellModel& model, const model::ExplicitMass& mass, double duration) {
  const solver::ExplicitOptions& o = *setup.explicit_scheme;
  const double steps = duration / mass.time_step;
  if (steps <= o.max_steps) return;
  const double fits = o.mass_scaling * (steps / o.max_steps) * (steps / o.max_steps);
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "the stable time step %.3g s needs %.3g steps for the %.4g s of the path, more than max_steps = %.3g; the smallest step "
                "is that of %s; mass_scaling = %.3g (or time_scaling) would fit",
                mass.time_step, steps, duration, o.max_steps, model::describe_element(model, mass.smallest_element).c_str(), fits);
  throw io::InputError(scene_file(setup), "solver.mass_scaling", io::format_number(o.mass_scaling), buf);
}

// Every newton.initial_increment of the load factor, and the marks. A resumed run's schedule is the
// fresh run's: the solver skips the output points passed before its checkpoint.
solver::ExplicitSchedule explicit_schedule(const FeRunSetup& setup, double duration) {
  solver::ExplicitSchedule schedule;
  schedule.duration = duration;
  schedule.output_interval = setup.newton.initial_increment;
  for (const Mark& m : setup.marks) schedule.stops.push_back(setup.load_map.lambda(m.travel));
  return schedule;
}

}  // namespace

FeRunOutcome FeRun::run_explicit(const nlohmann::json& head) {
  const solver::ExplicitOptions& o = *setup_.explicit_scheme;
  auto t0 = FeRunClock::now();
  // As for an implicit run: the input files' contents go into checkpoints and are compared on resume.
  const RunInputs inputs = files_.enabled() ? read_run_inputs(setup_.kind, setup_.input_files) : RunInputs{};
  // The Moving Spherical Tool instead of the penalty: the tool stays for its geometry, without force.
  if (setup_.contact.method == contact::ContactOptions::Method::mst) tool_->set_passive(true);
  model::ShellModel& shell = *shell_model();  // the constructor refused other families
  ExplicitDynamics dyn(setup_, shell, *constraints_);
  RunLog restored;
  if (control_.resume) {
    // The checkpoint is read (and refused with an InputError) before any output is touched.
    if (!files_.enabled()) throw std::logic_error("FeRun: a resume needs an output directory");
    read_run_checkpoint(*files_.directory(), inputs, model_.get(), nullptr, &dyn, &restored, observers_);
    t0 -= std::chrono::duration_cast<FeRunClock::duration>(std::chrono::duration<double>(restored.wall_seconds));
  } else {
    dyn.start();
  }
  const double duration = setup_.time_of_travel(setup_.load_map.length()) / o.time_scaling;
  check_step_count(setup_, shell, dyn.mass(), duration);
  model::MovingSphereContact* mst = dyn.mst();

  RunHeartbeat heartbeat(files_, head, control_.heartbeat_seconds);
  heartbeat.write();
  Stepper step(*this, inputs, t0, heartbeat);
  step.start_from(restored);
  step.checkpoints.every_marks = setup_.output.checkpoint_every;
  step.checkpoints.every_increments = setup_.output.checkpoint_increments;
  step.explicit_part = &dyn;
  if (control_.resume)
    for (auto& ob : observers_) ob->write(WriteReason::end);  // the rows a killed run wrote after its checkpoint are dropped
  else
    for (auto& ob : observers_) ob->at_start(*model_);

  IntervalForceFit fit;
  DynamicsView view;
  const auto after_step = [&](double dt) { fit.add(dt, mst ? mst->tool_force() : tool_->force()); };
  const auto at_output = [&](const solver::ExplicitInterval& iv) {
    dyn.record_output(iv.kinetic, model::energy_account(*model_).internal());
    view.steps = iv.steps;
    view.total_steps = iv.total_steps;
    view.time_step = iv.time_step;
    view.kinetic = iv.kinetic;
    view.damping_work = iv.damping_work;
    view.filtered_tool_force = fit.at_end(mst ? mst->tool_force() : tool_->force());
    view.contact_work = mst ? mst->statistics().work : 0.0;
    fit = IntervalForceFit{};  // before the stepper's checkpoint: the filter is not part of it
    solver::IncrementReport ir;
    ir.index = iv.index;
    ir.lambda = iv.lambda;
    ir.increment = iv.lambda - iv.lambda_before;
    ir.iterations = iv.steps;
    step.dynamics = &view;
    return step(ir);
  };
  const model::ExplicitMass& mass = dyn.mass();
  const auto bound = [&] { return model::current_time_step(shell, mass, o.safety, dyn.viscosity()); };
  const solver::ExplicitSummary r = dyn.solver().run(explicit_schedule(setup_, duration), bound, after_step, at_output);

  FeRunOutcome out = step.finish(r.completed, r.lambda, r.message, control_.resume ? restored.marks_reached : -1);
  out.counters.increments = step.log.increments;
  out.dynamics = dynamics_json(r, o, mass, duration, dyn.max_kinetic_over_internal(), view, mst, model::describe_element(shell, mass.smallest_element));
  return out;
}

}  // namespace spifit::scene
