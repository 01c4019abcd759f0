#pragma once
// Direct sparse solvers from SuiteSparse (docs/design/numerics-shell.md, "Sparse linear algebra"): UMFPACK for
// general (non-symmetric) tangents — large rotations, friction — and CHOLMOD for symmetric positive
// definite ones. The symbolic analysis (fill-reducing ordering) depends only on the pattern and is
// done once per pattern; each factorize() redoes only the numeric factorisation. Failures are
// statuses with a message (singular, not positive definite), never exceptions.
#include "forward/solver/sparse_matrix.hpp"

#include <memory>
#include <string>

namespace spifit::solver {

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual bool factorize(const SparseMatrix& a) = 0;
  virtual bool solve(const Eigen::VectorXd& b, Eigen::VectorXd* x) = 0;
  const std::string& error() const { return error_; }
  int symbolic_analyses() const { return symbolic_; }
  int numeric_factorisations() const { return numeric_; }
  // How the last analysed matrix is factorised (e.g. the split's domain and separator sizes);
  // empty when there is nothing to add to the solver's name.
  virtual std::string layout() const { return {}; }

 protected:
  std::string error_;
  int symbolic_ = 0, numeric_ = 0;
};

// automatic: CHOLMOD when the assembled matrix is symmetric (to 1e-10 of its largest entry),
// UMFPACK otherwise; decided at every factorisation by the Newton solver.
enum class LinearSolverKind { automatic, umfpack, cholmod };
const char* to_string(LinearSolverKind kind);
// "auto", "umfpack" or "cholmod"; false otherwise.
bool linear_solver_from_string(const std::string& s, LinearSolverKind* kind);
// umfpack or cholmod (automatic gives UMFPACK). CHOLMOD splits large systems in two halves
// factorised side by side (split_cholmod.hpp).
std::unique_ptr<LinearSolver> make_linear_solver(LinearSolverKind kind);
// CHOLMOD on the whole matrix at once (what the split uses below its size threshold).
std::unique_ptr<LinearSolver> make_one_piece_cholmod();

}  // namespace spifit::solver
