#include "forward/solver/linear_solver.hpp"

#include <cholmod.h>
#include <umfpack.h>

#include "forward/runtime/serial_openmp_scope.hpp"
#include "forward/solver/cholmod_views.hpp"
#include "forward/solver/split_cholmod.hpp"

namespace spifit::solver {

namespace {

// UMFPACK reads compressed columns; our CSR arrays read as CSC describe A^T, so the solve uses
// UMFPACK_At (x = (A^T)^T \ b = A \ b).
class Umfpack final : public LinearSolver {
 public:
  Umfpack() {
    umfpack_dl_defaults(control_);
    // FE tangents have a symmetric pattern and a strong diagonal: the symmetric strategy
    // (ordering of A + A^T, diagonal pivots preferred) fills far less than the unsymmetric
    // default. The ordering (AMD or METIS, whichever fills less) is chosen once per pattern.
    control_[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_BEST;
  }
  ~Umfpack() override { release(); }
  bool factorize(const SparseMatrix& a) override {
    const auto& p = a.pattern();
    if (pattern_ != &p || nnz_ != p.nonzeros()) {
      release();
      void* sym = nullptr;
      const long st = umfpack_dl_symbolic(p.rows, p.rows, p.row_ptr.data(), p.cols.data(), a.values().data(), &sym, control_, nullptr);
      if (st != UMFPACK_OK) return fail("UMFPACK symbolic analysis failed (status " + std::to_string(st) + ")");
      symbolic_ptr_ = sym;
      pattern_ = &p;
      nnz_ = p.nonzeros();
      ++symbolic_;
    }
    if (numeric_ptr_) umfpack_dl_free_numeric(&numeric_ptr_);
    const long st = umfpack_dl_numeric(p.row_ptr.data(), p.cols.data(), a.values().data(), symbolic_ptr_, &numeric_ptr_, control_, nullptr);
    ++numeric_;
    matrix_ = &a;
    if (st == UMFPACK_WARNING_singular_matrix) return fail("singular matrix (UMFPACK)");
    if (st != UMFPACK_OK) return fail("UMFPACK numeric factorisation failed (status " + std::to_string(st) + ")");
    error_.clear();
    return true;
  }
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd* x) override {
    if (!numeric_ptr_ || !matrix_) return fail("solve before factorize");
    const auto& p = matrix_->pattern();
    x->resize(p.rows);
    const long st = umfpack_dl_solve(UMFPACK_At, p.row_ptr.data(), p.cols.data(), matrix_->values().data(), x->data(), b.data(),
                                    numeric_ptr_, control_, nullptr);
    if (st != UMFPACK_OK) return fail("UMFPACK solve failed (status " + std::to_string(st) + ")");
    return true;
  }

 private:
  bool fail(const std::string& m) {
    error_ = m;
    return false;
  }
  void release() {
    if (numeric_ptr_) umfpack_dl_free_numeric(&numeric_ptr_);
    if (symbolic_ptr_) umfpack_dl_free_symbolic(&symbolic_ptr_);
    numeric_ptr_ = symbolic_ptr_ = nullptr;
    pattern_ = nullptr;
  }
  double control_[UMFPACK_CONTROL];
  void* symbolic_ptr_ = nullptr;
  void* numeric_ptr_ = nullptr;
  const SparsePattern* pattern_ = nullptr;
  const SparseMatrix* matrix_ = nullptr;
  long nnz_ = -1;
};

// CHOLMOD (long-index interface) on the symmetric matrix: the CSR arrays read as CSC are A^T =
// A. The fill-reducing ordering is chosen on them; the factorisations then get the permuted
// lower triangle ready-made (permuted_lower.hpp).
class Cholmod final : public LinearSolver {
 public:
  Cholmod() {
    cholmod_l_start(&common_);
    common_.print = 0;
    // Supernodal LL^T: a matrix that is not positive definite is detected (the default
    // simplicial LDL^T would factorise an indefinite matrix silently); the caller then falls
    // back to UMFPACK.
    common_.supernodal = CHOLMOD_SUPERNODAL;
    // Fill-reducing ordering chosen once per pattern: AMD or METIS nested dissection,
    // whichever gives the sparser factor (METIS wins on large 2-D meshes).
    common_.nmethods = 2;
    common_.method[0].ordering = CHOLMOD_AMD;
    common_.method[1].ordering = CHOLMOD_METIS;
  }
  ~Cholmod() override {
    if (factor_) cholmod_l_free_factor(&factor_, &common_);
    cholmod_l_finish(&common_);
  }
  bool factorize(const SparseMatrix& a) override {
    const auto& p = a.pattern();
    if ((pattern_ != &p || nnz_ != p.nonzeros()) && !analyse(p)) return false;
    permuted_.gather(a.values().data());
    int ok = 0;
    {
      const runtime::SerialOpenMpScope serial;  // CHOLMOD's own 4-thread regions cost more than they gain
      cholmod_sparse A = lower_csc_view(permuted_);
      ok = cholmod_l_factorize(&A, factor_, &common_);
    }
    ++numeric_;
    n_ = p.rows;
    if (!ok || common_.status == CHOLMOD_NOT_POSDEF) return fail("matrix not positive definite (CHOLMOD); use UMFPACK for this tangent");
    error_.clear();
    return true;
  }
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd* x) override {
    if (!factor_) return fail("solve before factorize");
    Eigen::VectorXd y = permuted_.to_pivots(b.data());
    cholmod_dense B = column_view(y.data(), n_);
    cholmod_dense* X = nullptr;
    {
      const runtime::SerialOpenMpScope serial;
      X = cholmod_l_solve(CHOLMOD_A, factor_, &B, &common_);
    }
    if (!X) return fail("CHOLMOD solve failed");
    x->resize(n_);
    permuted_.from_pivots(static_cast<const double*>(X->x), x->data());
    cholmod_l_free_dense(&X, &common_);
    return true;
  }

 private:
  // The ordering of the pattern, then the analysis of its permuted lower triangle.
  bool analyse(const SparsePattern& p) {
    if (factor_) cholmod_l_free_factor(&factor_, &common_);
    cholmod_sparse A = symmetric_csc_view(p.rows, p.row_ptr.data(), p.cols.data(), nullptr);
    cholmod_factor* ordered = cholmod_l_analyze(&A, &common_);
    if (!ordered) return fail("CHOLMOD symbolic analysis failed");
    permuted_ = permuted_lower(p.rows, p.row_ptr.data(), p.cols.data(), nullptr, static_cast<const long*>(ordered->Perm));
    cholmod_l_free_factor(&ordered, &common_);
    factor_ = analyse_as_ordered(permuted_, &common_);
    if (!factor_) return fail("CHOLMOD symbolic analysis of the permuted matrix failed");
    pattern_ = &p;
    nnz_ = p.nonzeros();
    ++symbolic_;
    return true;
  }
  bool fail(const std::string& m) {
    error_ = m;
    return false;
  }
  PermutedLower permuted_;
  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  const SparsePattern* pattern_ = nullptr;
  long nnz_ = -1, n_ = 0;
};

}  // namespace

const char* to_string(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::automatic: return "auto";
    case LinearSolverKind::umfpack: return "umfpack";
    case LinearSolverKind::cholmod: return "cholmod";
  }
  return "?";
}

bool linear_solver_from_string(const std::string& s, LinearSolverKind* kind) {
  for (auto k : {LinearSolverKind::automatic, LinearSolverKind::umfpack, LinearSolverKind::cholmod})
    if (s == to_string(k)) {
      *kind = k;
      return true;
    }
  return false;
}

std::unique_ptr<LinearSolver> make_linear_solver(LinearSolverKind kind) {
  if (kind == LinearSolverKind::cholmod) return make_split_cholmod();
  return std::make_unique<Umfpack>();
}

std::unique_ptr<LinearSolver> make_one_piece_cholmod() { return std::make_unique<Cholmod>(); }

}  // namespace spifit::solver
