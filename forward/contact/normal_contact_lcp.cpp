#include "forward/contact/normal_contact_lcp.hpp"

#include <Eigen/Cholesky>

#include <vector>

namespace spifit::contact {
namespace {

// The forces that close the gaps of the active points exactly, the others at zero.
Eigen::VectorXd forces_on(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const std::vector<char>& active) {
  std::vector<Eigen::Index> idx;
  for (Eigen::Index i = 0; i < q.size(); ++i)
    if (active[static_cast<std::size_t>(i)]) idx.push_back(i);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(q.size());
  const Eigen::MatrixXd A = M(idx, idx);
  const Eigen::VectorXd b = -q(idx);
  const Eigen::VectorXd z = A.ldlt().solve(b);
  out(idx) = z;
  return out;
}

}  // namespace

NormalContactSolution solve_normal_contact(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, double tolerance, int max_sets) {
  const Eigen::Index k = q.size();
  NormalContactSolution s;
  s.force = Eigen::VectorXd::Zero(k);
  std::vector<char> active(static_cast<std::size_t>(k), 0);
  Eigen::VectorXd& P = s.force;
  while (s.active_sets < max_sets) {
    // The most negative gap of an inactive point that a force can move.
    const Eigen::VectorXd w = M * P + q;
    Eigen::Index enter = -1;
    for (Eigen::Index i = 0; i < k; ++i)
      if (!active[static_cast<std::size_t>(i)] && M(i, i) > 0.0 && w(i) < -tolerance && (enter < 0 || w(i) < w(enter))) enter = i;
    if (enter < 0) {
      s.converged = true;
      return s;
    }
    active[static_cast<std::size_t>(enter)] = 1;
    // Solve on the set; where a force would turn negative, go as far as the first one reaching
    // zero, drop it, and solve again.
    while (s.active_sets < max_sets) {
      ++s.active_sets;
      const Eigen::VectorXd z = forces_on(M, q, active);
      double alpha = 1.0;
      Eigen::Index leave = -1;
      for (Eigen::Index i = 0; i < k; ++i)
        if (active[static_cast<std::size_t>(i)] && z(i) <= 0.0 && i != enter) {
          const double a = P(i) / (P(i) - z(i));
          if (a < alpha) { alpha = a; leave = i; }
        }
      if (leave < 0 && z(enter) > 0.0) {
        P = z;
        break;
      }
      if (leave < 0) {  // the entering point itself cannot carry a force: it stays out
        active[static_cast<std::size_t>(enter)] = 0;
        for (Eigen::Index i = 0; i < k; ++i) P(i) = active[static_cast<std::size_t>(i)] ? P(i) : 0.0;
        s.converged = false;
        return s;
      }
      P += alpha * (z - P);
      for (Eigen::Index i = 0; i < k; ++i)
        if (active[static_cast<std::size_t>(i)] && i != enter && P(i) <= 0.0) {
          P(i) = 0.0;
          active[static_cast<std::size_t>(i)] = 0;
        }
      P(enter) = std::max(P(enter), 0.0);
    }
  }
  return s;
}

}  // namespace spifit::contact
