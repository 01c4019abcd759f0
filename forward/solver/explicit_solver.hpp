#pragma once
// Explicit dynamics (docs/design/explicit.md; thesis §5.1): central differences in the
// velocity-Verlet form of thesis eqs. 5.2-5.5 with a diagonal mass matrix,
//   v(n+1/2) = v(n) + dt/2 a(n),   u(n+1) = u(n) + dt v(n+1/2),
//   a(n+1) = M^-1 (f_ext - f_int)(u(n+1)) - c v(n+1/2),   v(n+1) = v(n+1/2) + dt/2 a(n+1),
// on the reduced unknowns of the constraints (tied DOFs share their masters' velocity; the
// reduced mass is diag(T^T M T)), over the same NonlinearProblem the Newton solver uses: every
// step moves the load factor (the tool), evaluates the element residuals at the new
// configuration (integrated from the last step's states, which are committed every step) and
// commits. The load factor runs from lambda_start to lambda_end over `duration` seconds; the
// run stops exactly at every output point and calls back there. Its state at an output point
// (state()) restored into a solver built alike (restore()) continues the run bit for bit.
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/explicit_options.hpp"
#include "forward/solver/explicit_state.hpp"
#include "forward/solver/nonlinear_problem.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace spifit::solver {

// The state at an output point.
struct ExplicitInterval {
  int index = 0;               // output points so far, this one included
  double lambda = 0.0;         // load factor reached
  double lambda_before = 0.0;  // at the previous output point
  int steps = 0;               // steps since the previous output point
  long total_steps = 0;
  double time = 0.0;           // simulated time [s]
  double time_step = 0.0;      // the steps' size in this interval [s]
  double kinetic = 0.0;        // 1/2 v M v [N mm]
  double damping_work = 0.0;   // work of the damping forces so far [N mm]
};

struct ExplicitSummary {
  bool completed = false;      // reached lambda_end
  double lambda = 0.0;
  std::string message;         // why it stopped early (where and when)
  long steps = 0, cut_steps = 0;
  double time = 0.0;
  double min_step = 0.0, max_step = 0.0;
};

struct ExplicitSchedule {
  double lambda_start = 0.0, lambda_end = 1.0;
  double duration = 1.0;          // simulated seconds for lambda 0 -> 1
  double output_interval = 0.1;   // of the load factor between output points
  std::vector<double> stops;      // further load factors that are output points (marks)
};

class ExplicitSolver {
 public:
  // mass: per DOF of the problem (translations and rotations). std::invalid_argument when a
  // reduced unknown gets no mass, or the options are invalid.
  ExplicitSolver(NonlinearProblem& problem, const DofConstraints& constraints, const Eigen::VectorXd& mass, ExplicitOptions options);

  // Reduced velocities (initial conditions of tests; zero by default).
  Eigen::VectorXd& velocity() { return state_.v; }
  const Eigen::VectorXd& reduced_mass() const { return m_; }
  double kinetic_energy() const { return 0.5 * state_.v.dot(m_.cwiseProduct(state_.v)); }

  // The state after the last step; at an output point (in the callback) where a resumed run
  // goes on from (a checkpoint).
  const ExplicitState& state() const { return state_; }
  // Continues from a saved state: run() with the same schedule then skips the output points
  // passed and the first acceleration. std::invalid_argument for a state of another size.
  void restore(ExplicitState state);

  // Current stable step [s] (re-estimated every options.recheck_every steps; the steps of an
  // interval are never longer than the bound at its start).
  using StepBound = std::function<double()>;
  // After every committed step, with its size [s].
  using AfterStep = std::function<void(double dt)>;
  // At every output point; false stops the run.
  using Callback = std::function<bool(const ExplicitInterval&)>;
  ExplicitSummary run(const ExplicitSchedule& schedule, const StepBound& bound, const AfterStep& after_step, const Callback& callback);

  // Forces decided after each step for the next one (the Moving Spherical Tool contact, thesis
  // §5.2): given the step size, the load factor the next step reaches and the reduced increment
  // it would take without them, the forces on the model (full DOF vector), added to the
  // acceleration of the step just taken. Set before run().
  using ContactForces = std::function<Eigen::VectorXd(double dt, double lambda_next, const Eigen::VectorXd& next_increment)>;
  void set_contact_forces(ContactForces f) { contact_ = std::move(f); }

  // Forces that depend on the velocity (the bulk viscosity, model/bulk_viscosity.hpp): given
  // the reduced velocity, the forces at the committed configuration with the sign of internal
  // forces (full DOF vector). Like the mass-proportional damping they take the half-step
  // velocity, and their work counts as damping work. Set before run().
  using VelocityForces = std::function<Eigen::VectorXd(const Eigen::VectorXd& v)>;
  void set_velocity_forces(VelocityForces f) { velocity_forces_ = std::move(f); }

 private:
  NonlinearProblem& problem_;
  const DofConstraints& constraints_;
  ExplicitOptions options_;
  Eigen::VectorXd m_;             // reduced mass
  ExplicitState state_;           // velocity, acceleration, load factor, time, counters
  Eigen::VectorXd prescribed_rate_;  // prescribed values per unit load factor (full DOF vector)
  bool moves_prescribed_ = false;
  std::vector<Eigen::VectorXd> re_;
  std::vector<ElementEvaluation> ev_;
  ContactForces contact_;
  VelocityForces velocity_forces_;
  // The acceleration of the internal (residual r) and damping forces at velocity v; keeps the
  // damping force and adds its work over this step's move dt v (dt = 0: none).
  Eigen::VectorXd acceleration(const Eigen::VectorXd& r, const Eigen::VectorXd& v, double dt);
  // Residual (internal - external) reduced at the problem's trial configuration and lambda;
  // false with the failure when an element fails.
  bool residual(double lambda, Eigen::VectorXd* r, ElementEvaluation* failure);
  // The first acceleration, at the committed state and lambda; false when an element fails.
  bool start(double lambda, ElementEvaluation* failure);
  // One step of dt from lambda0 to lambda1: false (problem reverted) when an element fails.
  bool step(double dt, double lambda0, double lambda1, ElementEvaluation* failure);
  // The first acceleration and step bound of a fresh run; false with the message when an element fails.
  bool begin(double lambda, const StepBound& bound, std::string* message);
  // Steps to the output point (the steps of the interval equal, each within the step bound,
  // re-estimated every options_.recheck_every steps); false with the message when it fails.
  bool advance(double point, double duration, const StepBound& bound, const AfterStep& after_step, ExplicitInterval* iv, std::string* message);
  // One step of dt to lambda1 (cut into quarters when it fails), counted; taken: its size.
  bool take_step(double dt, double lambda1, const AfterStep& after_step, double* taken, std::string* message);
  ExplicitSummary summary(bool completed, std::string message) const;
  // A failed step taken again as four quarters; false (with the load factor reached) when one fails.
  bool quarter_steps(double dt, double lambda0, double lambda1, const AfterStep& after_step, double* time, double* reached,
                     ElementEvaluation* failure);
  // The DOF of the first non-finite acceleration, named by the problem.
  std::string non_finite_dof() const;
};

}  // namespace spifit::solver
