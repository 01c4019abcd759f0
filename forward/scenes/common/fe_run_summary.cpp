#include "forward/scenes/common/fe_run_summary.hpp"

namespace spifit::scene {

nlohmann::json vector_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

void add_fe_run_summary(nlohmann::json& j, const FeRunOutcome& run, const ToolForceHistory& force, const ForceRipple& ripple,
                        const model::ModelEnergies& en,
                        const std::string& energies_units) {
  const solver::NewtonCounters& c = run.counters;
  j["increments"] = c.increments;
  j["newton_iterations"] = c.iterations;
  j["cutbacks"] = c.cutbacks;
  j["factorisations"] = c.factorisations();
  j["factorisations_by_solver"] = {{"cholmod", c.cholmod_factorisations}, {"umfpack", c.umfpack_factorisations}};
  j["assemblies"] = {{"with_tangent", c.tangent_assemblies}, {"residual_only", c.residual_assemblies}, {"tangent_after_all", c.tangent_reassemblies}};
  j["profile_seconds"] = {{"elements", c.element_seconds}, {"assembly", c.scatter_seconds}, {"linear_solver", c.linear_seconds}};
  // Increments accepted with viscous forces (NewtonOptions::stabilisation): their dissipated
  // work against the tool's work, and the largest out-of-balance one was accepted with.
  j["stabilised"] = {{"increments", c.stabilised_increments},
                     {"viscous_work", c.viscous_work},
                     {"viscous_work_over_tool_work", en.external_work > 0.0 ? c.viscous_work / en.external_work : 0.0},
                     {"max_viscous_force", c.max_viscous_force}};
  if (!run.sensitivity_solves.is_null()) j["sensitivity_solves"] = run.sensitivity_solves;
  j["travel_reached"] = run.travel_reached;
  j["peak_force"] = vector_json(force.peak());
  j["final_force"] = vector_json(force.final_force());
  j["max_penetration"] = force.max_penetration();
  j["max_surface_penetration"] = force.max_surface_penetration();
  // Steady windows looked at: 0 when the increments are too coarse to resolve a ripple.
  j["force_ripple"] = {{"amplitude_over_peak_force", ripple.amplitude},
                       {"component", std::string(1, "xyz"[ripple.component])},
                       {"travel", ripple.travel},
                       {"window", ripple.window},
                       {"windows", ripple.windows}};
  j["energies"] = {{"external_work", en.external_work},
                   {"elastic", en.elastic},
                   {"plastic", en.plastic},
                   {"transverse_shear", en.transverse_shear},
                   {"contact_stored", en.contact_stored},
                   {"friction_dissipation", en.friction_dissipation},
                   {"contact_offset_release", en.contact_offset_release},
                   {"kinetic", en.kinetic},
                   {"balance_error", en.balance_error()},
                   {"relative_balance_error", en.external_work != 0.0 ? en.balance_error() / en.external_work : 0.0},
                   {"units", energies_units}};
  j["checkpoints"] = {{"file", "checkpoint/state.bin"},
                      {"every_marks", run.checkpoints.every_marks},
                      {"every_increments", run.checkpoints.every_increments},
                      {"written", run.checkpoints.written},
                      {"bytes", run.checkpoints.bytes},
                      {"write_seconds", run.checkpoints.write_seconds}};
  if (run.resumed_at_mark >= 0) j["resumed_at_mark"] = run.resumed_at_mark;
  if (!run.dynamics.is_null()) {
    j["explicit"] = run.dynamics;
    j["energies"]["damping"] = en.damping;
  }
}

}  // namespace spifit::scene
