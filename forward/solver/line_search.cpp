#include "forward/solver/line_search.hpp"

#include <algorithm>
#include <cmath>

namespace spifit::solver {

LineSearch::Step LineSearch::run(const Eigen::VectorXd& du, const Eigen::VectorXd& r, const Trial& trial) const {
  const double s0 = du.dot(r);
  Step step;
  for (int ls = 0;; ++ls) {
    const Eigen::VectorXd* residual = trial(step.alpha);
    step.ok = residual != nullptr;
    if (!step.ok) {
      if (ls < options_.max_line_search && step.alpha > 0.1) {  // a failed trial: try a shorter step first
        step.alpha *= 0.5;
        ++step.searches;
        continue;
      }
      return step;
    }
    if (!options_.line_search || ls >= options_.max_line_search || !(s0 < 0.0)) return step;
    const double s1 = du.dot(*residual);
    if (std::abs(s1) <= 0.8 * std::abs(s0) || !std::isfinite(s1)) return step;
    const double next = std::clamp(step.alpha * s0 / (s0 - s1), 0.1, 1.0);
    if (std::abs(next - step.alpha) < 0.05) return step;
    step.alpha = next;
    ++step.searches;
  }
}

}  // namespace spifit::solver
