#include "forward/solver/preconditioned_gmres.hpp"

#include <cmath>
#include <vector>

namespace spifit::solver {

// Arnoldi on K M^-1 with modified Gram-Schmidt; the least-squares problem min |beta e1 - H y| is
// kept triangular by Givens rotations, whose last right-hand side entry is the residual norm.
GmresResult preconditioned_gmres(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& apply,
                                 const std::function<bool(const Eigen::VectorXd&, Eigen::VectorXd*)>& precondition,
                                 const Eigen::VectorXd& b, Eigen::VectorXd* x, double tolerance, int max_iterations) {
  GmresResult out;
  *x = Eigen::VectorXd::Zero(b.size());
  const double beta = b.norm();
  if (beta == 0.0) {
    out.converged = true;
    return out;
  }
  const int m = max_iterations;
  std::vector<Eigen::VectorXd> v{b / beta}, z;  // Krylov basis, its preconditioned images
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m + 1, m);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1), cs = Eigen::VectorXd::Zero(m), sn = Eigen::VectorXd::Zero(m);
  g(0) = beta;
  int k = 0;
  for (; k < m; ++k) {
    Eigen::VectorXd zk;
    if (!precondition(v[static_cast<std::size_t>(k)], &zk) || !zk.allFinite()) break;
    Eigen::VectorXd w = apply(zk);
    z.push_back(std::move(zk));
    for (int i = 0; i <= k; ++i) {
      h(i, k) = w.dot(v[static_cast<std::size_t>(i)]);
      w -= h(i, k) * v[static_cast<std::size_t>(i)];
    }
    const double sub = w.norm();
    h(k + 1, k) = sub;
    for (int i = 0; i < k; ++i) {  // the earlier rotations on the new column
      const double a = h(i, k), c = h(i + 1, k);
      h(i, k) = cs(i) * a + sn(i) * c;
      h(i + 1, k) = -sn(i) * a + cs(i) * c;
    }
    const double r = std::hypot(h(k, k), h(k + 1, k));
    if (r == 0.0) break;
    cs(k) = h(k, k) / r;
    sn(k) = h(k + 1, k) / r;
    h(k, k) = r;
    h(k + 1, k) = 0.0;
    g(k + 1) = -sn(k) * g(k);
    g(k) = cs(k) * g(k);
    out.iterations = k + 1;
    out.relative_residual = std::abs(g(k + 1)) / beta;
    if (out.relative_residual <= tolerance || sub == 0.0) {  // sub = 0: the Krylov space is invariant, x exact
      out.converged = out.relative_residual <= tolerance;
      ++k;
      break;
    }
    v.push_back(w / sub);
  }
  if (k == 0) return out;
  // y from the triangular system, x = Z y.
  Eigen::VectorXd y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  for (int i = 0; i < k; ++i) *x += y(i) * z[static_cast<std::size_t>(i)];
  return out;
}

}  // namespace spifit::solver
