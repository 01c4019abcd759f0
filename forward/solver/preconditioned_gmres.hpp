#pragma once
// GMRES (Saad & Schultz 1986) with right preconditioning, for the direct differentiation's solves
// with the exact converged tangent K (docs/design/sensitivities.md, "Cost"): preconditioned by the
// factor Newton holds anyway (the tangent at the previous iterate, or its symmetric part), it
// converges in a few back-substitutions where a factorisation of K of its own would cost far more.
// Right preconditioning keeps the true residual |b - K x| as the quantity tested. No restarts: it
// is meant for a preconditioner close to K, and gives up after max_iterations.
#include <Eigen/Core>

#include <functional>

namespace spifit::solver {

struct GmresResult {
  bool converged = false;
  int iterations = 0;              // preconditioner applications
  double relative_residual = 0.0;  // |b - K x| / |b| (from the Arnoldi relation)
};

// Solves K x = b from x = 0: apply(v) = K v; precondition(v, &z) sets z = M^-1 v (false: failed).
// Converged when |b - K x| <= tolerance |b|; b = 0 gives x = 0.
GmresResult preconditioned_gmres(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& apply,
                                 const std::function<bool(const Eigen::VectorXd&, Eigen::VectorXd*)>& precondition,
                                 const Eigen::VectorXd& b, Eigen::VectorXd* x, double tolerance, int max_iterations);

}  // namespace spifit::solver
