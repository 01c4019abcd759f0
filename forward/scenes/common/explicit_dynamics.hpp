#pragma once
// The explicit scheme's part of an FeRun (fe_run_explicit.cpp; docs/design/explicit.md): the
// mass and time-step state, the solver, the Moving Spherical Tool when the contact is one, and
// the kinetic and internal energies at the output points (the summary's quasi-static ratio).
// Built at a fresh run's start, or restored from the run's checkpoint. A resumed run keeps the
// mass and element steps of its start: rebuilt from the deformed geometry they would differ,
// and so would every step after.
#include "forward/model/bulk_viscosity.hpp"
#include "forward/model/explicit_mass.hpp"
#include "forward/model/moving_sphere_contact.hpp"
#include "forward/scenes/common/fe_run.hpp"
#include "forward/scenes/common/run_checkpoint.hpp"
#include "forward/solver/explicit_solver.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace spifit::scene {

class ExplicitDynamics : public CheckpointPart {
 public:
  // setup.explicit_scheme must be set; the references must outlive this.
  ExplicitDynamics(const FeRunSetup& setup, model::ShellModel& model, const solver::DofConstraints& constraints);

  // A fresh run: the mass from the model's committed (initial) state, then the solver and contact.
  void start();
  solver::ExplicitSolver& solver() { return *solver_; }
  const model::ExplicitMass& mass() const { return mass_; }
  model::MovingSphereContact* mst() { return mst_.get(); }  // null with the penalty contact
  const model::BulkViscosity* viscosity() const { return viscosity_.get(); }  // null without bulk viscosity

  // At every output point.
  void record_output(double kinetic, double internal) { kinetic_internal_.push_back({kinetic, internal}); }
  // The largest kinetic over internal energy once the internal energy has reached a tenth of its
  // final value (before, both are near zero and their ratio says nothing).
  double max_kinetic_over_internal() const;

  // Checkpoints (section "explicit"): the options that decide the run, the mass, the solver's
  // state, the MST's, the energies at the output points. restore() refuses (io::ArchiveError)
  // a checkpoint of other options, naming the first that differs.
  void save(io::BinaryWriter& w) const override;
  void restore(io::BinaryReader& r) override;

 private:
  const FeRunSetup& setup_;
  model::ShellModel& model_;
  const solver::DofConstraints& constraints_;
  model::ExplicitMass mass_;
  std::unique_ptr<solver::ExplicitSolver> solver_;
  std::unique_ptr<model::MovingSphereContact> mst_;
  std::unique_ptr<model::BulkViscosity> viscosity_;
  std::vector<std::pair<double, double>> kinetic_internal_;

  model::ExplicitMassInputs mass_inputs() const;
  // The solver on mass_, the bulk viscosity when asked for, and the MST (its forces fed to the
  // solver) when the contact is one.
  void build();
};

}  // namespace spifit::scene
