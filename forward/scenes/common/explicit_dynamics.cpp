#include "forward/scenes/common/explicit_dynamics.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/io/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace spifit::scene {
namespace {

bool uses_mst(const FeRunSetup& s) { return s.contact.method == contact::ContactOptions::Method::mst; }

// The largest penalty the contact uses (normal or tangential): it bounds the stable step too.
double contact_stiffness(const contact::ContactOptions& c) { return std::max(c.penalty, c.tangential_penalty); }

// Every input that decides how an explicit run goes on and is not in the saved state, by the
// scene's key where it has one. A resume must run with the same (compared bit for bit): the
// scene file's contents are compared too, but a scene changed in memory (tests, sweeps) is not.
std::vector<std::pair<std::string, double>> decisive_options(const FeRunSetup& s) {
  const solver::ExplicitOptions& o = *s.explicit_scheme;
  return {{"solver.mass_scaling", o.mass_scaling},
          {"solver.rotational_mass_scaling", o.rotational_scaling},
          {"solver.target_time_step", o.target_time_step},
          {"solver.time_scaling", o.time_scaling},
          {"solver.damping", o.damping},
          {"solver.bulk_viscosity_linear", o.bulk_viscosity_linear},
          {"solver.bulk_viscosity_quadratic", o.bulk_viscosity_quadratic},
          {"solver.time_step_safety", o.safety},
          {"solver.max_steps", o.max_steps},
          {"the steps between time-step re-estimates", static_cast<double>(o.recheck_every)},
          {"contact.method (1: mst, 0: penalty)", uses_mst(s) ? 1.0 : 0.0},
          {"the output interval (load factor)", s.newton.initial_increment},
          {"the density", s.density},
          {"the contact penalty", contact_stiffness(s.contact)},
          {"contact.friction", s.contact.friction},
          {"the tool radius", s.tool_radius}};
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void check_options(io::BinaryReader& r, const FeRunSetup& setup) {
  const auto mine = decisive_options(setup);
  r.section("explicit_options");
  r.expect_count("explicit options", static_cast<std::int64_t>(mine.size()));
  for (const auto& [name, value] : mine) {
    const std::string saved_name = r.string();
    const double saved = r.f64();
    if (saved_name != name) throw io::ArchiveError("explicit option \"" + saved_name + "\" where this run has \"" + name + "\"");
    if (!same_bits(saved, value))
      throw io::ArchiveError("written with other explicit options: " + name + " = " + io::format_number(saved) + " in the checkpoint, " +
                             io::format_number(value) + " in this run; resume with the options it started with");
  }
}

}  // namespace

ExplicitDynamics::ExplicitDynamics(const FeRunSetup& setup, model::ShellModel& model, const solver::DofConstraints& constraints)
    : setup_(setup), model_(model), constraints_(constraints) {}

model::ExplicitMassInputs ExplicitDynamics::mass_inputs() const {
  model::ExplicitMassInputs in;
  in.density = setup_.density;
  in.contact_stiffness = contact_stiffness(setup_.contact);
  in.options = *setup_.explicit_scheme;
  return in;
}

void ExplicitDynamics::start() {
  mass_ = model::explicit_mass(model_, mass_inputs());
  build();
}

void ExplicitDynamics::build() {
  const solver::ExplicitOptions& o = *setup_.explicit_scheme;
  solver_ = std::make_unique<solver::ExplicitSolver>(model_, constraints_, mass_.diagonal, o);
  if (o.bulk_viscosity_linear > 0.0 || o.bulk_viscosity_quadratic > 0.0) {
    // Each element's plane-stress wave speed at its scaled density.
    std::vector<double> density, wave_speed;
    const material::MaterialParams<double>& m = setup_.material;
    for (double f : mass_.element_factor) {
      density.push_back(setup_.density * f);
      wave_speed.push_back(std::sqrt(m.E / (density.back() * (1.0 - m.nu * m.nu))));
    }
    viscosity_ = std::make_unique<model::BulkViscosity>(model_, constraints_, std::move(density), std::move(wave_speed), o.bulk_viscosity_linear,
                                                        o.bulk_viscosity_quadratic);
    model::BulkViscosity* bv = viscosity_.get();
    solver_->set_velocity_forces([bv](const Eigen::VectorXd& v) { return bv->forces(v); });
  }
  if (!uses_mst(setup_)) return;
  const toolpath::ToolPath& path = setup_.tool_path;
  const LoadMap& map = setup_.load_map;
  mst_ = std::make_unique<model::MovingSphereContact>(
      model_, constraints_, solver_->reduced_mass(), setup_.tool_radius, setup_.contact.friction,
      [&path, &map](double lambda) { return path.at_distance(map.travel(lambda)); }, setup_.tool_copies_deg);
  model::MovingSphereContact* mst = mst_.get();
  solver_->set_contact_forces([mst](double dt, double lambda_next, const Eigen::VectorXd& next) { return mst->forces(dt, lambda_next, next); });
}

double ExplicitDynamics::max_kinetic_over_internal() const {
  double ratio = 0.0;
  if (kinetic_internal_.empty()) return ratio;
  const double final_internal = kinetic_internal_.back().second;
  for (const auto& [k, e] : kinetic_internal_)
    if (e > 0.1 * final_internal && e > 0.0) ratio = std::max(ratio, k / e);
  return ratio;
}

void ExplicitDynamics::save(io::BinaryWriter& w) const {
  const auto options = decisive_options(setup_);
  w.section("explicit_options");
  w.i64(static_cast<std::int64_t>(options.size()));
  for (const auto& [name, value] : options) {
    w.string(name);
    w.f64(value);
  }
  model::save_explicit_mass(w, mass_);
  solver::save_explicit_state(w, solver_->state());
  if (mst_) mst_->save_state(w);
  w.section("output_energies");
  std::vector<double> kinetic, internal;
  for (const auto& [k, e] : kinetic_internal_) {
    kinetic.push_back(k);
    internal.push_back(e);
  }
  w.f64s(kinetic);
  w.f64s(internal);
}

void ExplicitDynamics::restore(io::BinaryReader& r) {
  check_options(r, setup_);
  mass_ = model::load_explicit_mass(r, model_.num_dofs(), model_.num_elements());
  build();
  solver::ExplicitState state = solver::load_explicit_state(r);
  if (state.v.size() != solver_->reduced_mass().size()) throw io::ArchiveError("explicit state of another model size");
  solver_->restore(std::move(state));
  if (mst_) mst_->load_state(r);
  r.section("output_energies");
  const std::vector<double> kinetic = r.f64s(), internal = r.f64s();
  if (kinetic.size() != internal.size()) throw io::ArchiveError("output energies of different lengths");
  kinetic_internal_.clear();
  for (std::size_t i = 0; i < kinetic.size(); ++i) kinetic_internal_.push_back({kinetic[i], internal[i]});
}

}  // namespace spifit::scene
