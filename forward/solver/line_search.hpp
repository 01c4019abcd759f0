#pragma once
// Step length along a Newton correction du (docs/design/numerics-shell.md, "Global solution", Line
// search): a trial where an element fails is halved; optionally, the energy line search
// (Crisfield) takes secant steps on s(alpha) = du . r(alpha) until |s| has dropped to 0.8 |s(0)|.
#include "forward/solver/newton_options.hpp"

#include <Eigen/Core>

#include <functional>

namespace spifit::solver {

class LineSearch {
 public:
  explicit LineSearch(const NewtonOptions& options) : options_(options) {}
  // Evaluates the trial iterate + alpha du: its residual, or null when an element fails there.
  using Trial = std::function<const Eigen::VectorXd*(double alpha)>;
  struct Step {
    bool ok = false;      // false: an element failed at every trial allowed
    double alpha = 1.0;   // the step of the last trial (the one to accept when ok)
    int searches = 0;     // trials after the first (halvings and secant steps)
  };
  // r: the residual at the current iterate (alpha = 0). The last trial evaluated is the one
  // returned.
  Step run(const Eigen::VectorXd& du, const Eigen::VectorXd& r, const Trial& trial) const;

 private:
  const NewtonOptions& options_;
};

}  // namespace spifit::solver
