#include "forward/solver/predictor.hpp"

namespace spifit::solver {

Eigen::VectorXd Predictor::iterate(double dl, const Eigen::VectorXd& dg) const {
  const double scale = dl / size_;
  return scale * last_ + dg;
}

void Predictor::record(const NonlinearProblem& problem, const DofConstraints& constraints, double lambda0, double lambda1) {
  last_ = problem.increment_from_committed() - constraints.prescribed_values(lambda1 - lambda0);
  size_ = lambda1 - lambda0;
}

void Predictor::restore(const Eigen::VectorXd& last_increment, double size) {
  last_ = last_increment;
  size_ = size;
}

}  // namespace spifit::solver
