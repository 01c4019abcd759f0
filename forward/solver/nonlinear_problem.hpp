#pragma once
// What the implicit solver needs from a model (MFEM's Operator: residual and gradient; MGIS's
// s0/s1 states): element residuals and tangents at a trial configuration, external forces,
// and the configuration bookkeeping. Configurations: committed (last converged increment),
// iterate (last accepted Newton iterate) and trial (iterate + alpha x correction, used by the
// line search). Element states are always integrated from the committed state.
#include <Eigen/Core>

#include <string>
#include <vector>

namespace spifit::solver {

struct ElementEvaluation {
  bool ok = true;
  std::string where;             // e.g. "element 12, point 3, layer 0"
  std::string reason;
  double suggested_scale = 1.0;  // < 1 on failure
};

class NonlinearProblem {
 public:
  virtual ~NonlinearProblem() = default;
  virtual int num_dofs() const = 0;
  virtual const std::vector<std::vector<int>>& element_dofs() const = 0;
  // Residual re = internal - external element forces, tangent ke = d re / d u at the trial
  // configuration (ke may be null). Called concurrently for different e.
  virtual ElementEvaluation evaluate_element(int e, Eigen::VectorXd* re, Eigen::MatrixXd* ke) = 0;
  // Called at the start of every increment attempt (after revert): time-dependent boundary
  // conditions such as the tool position move to lambda1.
  virtual void begin_increment(double lambda0, double lambda1) { (void)lambda0; (void)lambda1; }
  // Concentrated external forces at load factor lambda (full DOF vector).
  virtual Eigen::VectorXd external_forces(double lambda) const = 0;
  // trial = iterate (+) alpha x delta (delta: full DOF correction; rotations compose).
  virtual void set_trial(const Eigen::VectorXd& delta, double alpha) = 0;
  virtual void accept_trial() = 0;      // iterate = trial
  virtual void commit(double lambda) = 0;  // committed = iterate; element states committed
  virtual void revert() = 0;            // iterate = trial = committed
  // Displacement-like value of each DOF in the iterate relative to the committed state
  // (prescribed DOFs are driven to their targets through it).
  virtual Eigen::VectorXd increment_from_committed() const = 0;
  // Direct differentiation (docs/design/sensitivities.md). The number of parameters whose
  // derivatives the problem carries (0: none). After every converged increment, before
  // commit(), the solver asks for the pseudo-load at the converged iterate (the residual's
  // derivative with respect to each parameter at fixed DOFs: full DOF vectors, one column per
  // parameter), solves with the tangent there, and hands back the DOFs' derivatives (full
  // vectors, zero at prescribed DOFs), from which the problem's state derivatives follow.
  virtual int sensitivity_count() const { return 0; }
  virtual ElementEvaluation sensitivity_load(Eigen::MatrixXd* load) {
    (void)load;
    return {false, "sensitivity_load", "the problem has no parameter sensitivities", 1.0};
  }
  virtual ElementEvaluation update_sensitivities(const Eigen::MatrixXd& du) {
    (void)du;
    return {false, "update_sensitivities", "the problem has no parameter sensitivities", 1.0};
  }
  // Whether the tangent of the last assembly was the residual's exact derivative. A problem may
  // give Newton another tangent where that helps it (a shell layer starting an increment at rest
  // takes its last elastic-plastic tangent); the solve for the derivatives needs the exact one:
  // set_exact_tangents(true) makes the next assemblies exact without changing the state they
  // leave (the same trial states, and what the next increment starts from).
  virtual bool tangent_was_exact() const { return true; }
  virtual void set_exact_tangents(bool exact) { (void)exact; }
  // Names a DOF for messages (where a Newton correction was largest when an increment failed).
  virtual std::string describe_dof(int dof) const { return "DOF " + std::to_string(dof); }
};

}  // namespace spifit::solver
