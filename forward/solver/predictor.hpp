#pragma once
// The extrapolated first iterate of an increment (NewtonOptions::extrapolate;
// docs/design/numerics-shell.md, "Global solution", Predictor): the free part of the last converged
// increment, scaled to the new increment's size.
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/nonlinear_problem.hpp"

#include <Eigen/Core>

namespace spifit::solver {

class Predictor {
 public:
  // Whether there is a last increment for a problem of num_dofs DOFs.
  bool available(int num_dofs) const { return size_ > 0.0 && last_.size() == num_dofs; }
  // The trial displacement of an increment of load-factor size dl from the committed state:
  // the last increment x dl / its size, plus the increment's prescribed values dg.
  Eigen::VectorXd iterate(double dl, const Eigen::VectorXd& dg) const;
  // Remembers the converged increment from lambda0 to lambda1 (before the problem commits it):
  // the problem's increment from the committed state less the prescribed part.
  void record(const NonlinearProblem& problem, const DofConstraints& constraints, double lambda0, double lambda1);

  const Eigen::VectorXd& last_increment() const { return last_; }  // full DOF vector
  double last_size() const { return size_; }
  void restore(const Eigen::VectorXd& last_increment, double size);

 private:
  Eigen::VectorXd last_;
  double size_ = 0.0;
};

}  // namespace spifit::solver
