#pragma once
// Two-domain Cholesky (docs/design/numerics-shell.md, "Split factorisation"): the symmetric positive
// definite tangent K is cut by a node separator S (METIS, through CHOLMOD's bisector) into two
// domains D0 and D1 that share no entry. Each half K_h = K[D_h + S, D_h + S] is a principal
// submatrix of K, so it is positive definite; CHOLMOD factorises both halves at the same time
// (one thread each), with the separator ordered last (constrained AMD), so that
//   L_h = [L_aa 0; L_ba L_cc],  L_cc L_cc^T = C - B_h^T A_h^{-1} B_h.
// The Schur complement of K on S is then S = L_cc,0 L_cc,0^T + L_cc,1 L_cc,1^T - C (dense, a few
// hundred unknowns), factorised by a dense Cholesky. A solve is a forward substitution in each
// half, the dense separator solve, and a back substitution in each half.
//
// Why: CHOLMOD 5.12 factorises serially here (its supernodes are too small for a second BLAS
// thread), so on two cores the second one idled through 40 % of every Newton iteration.
// Results do not depend on the number of threads (the halves are independent and combined in
// a fixed order); they differ from the one-piece factorisation only by rounding.
#include "forward/solver/linear_solver.hpp"

#include <memory>

namespace spifit::solver {

// Below this many unknowns the one-piece CHOLMOD factorisation is used (the split gains
// nothing on small systems).
constexpr int kSplitCholmodMinUnknowns = 4000;

std::unique_ptr<LinearSolver> make_split_cholmod();

}  // namespace spifit::solver
