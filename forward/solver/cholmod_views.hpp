#pragma once
// CHOLMOD headers over spifit's own arrays (no copy): the one-piece and the split CHOLMOD
// (linear_solver.cpp, split_cholmod.cpp) hand CHOLMOD the same kinds of views.
#include <cholmod.h>

#include "forward/solver/permuted_lower.hpp"

namespace spifit::solver {

// A symmetric n x n matrix stored with both triangles in CSR, read as CSC (the same matrix);
// stype = 1: CHOLMOD uses the upper triangle. values == nullptr: the pattern alone.
inline cholmod_sparse symmetric_csc_view(long n, const long* row_ptr, const long* cols, const double* values) {
  cholmod_sparse A;
  A.nrow = A.ncol = static_cast<std::size_t>(n);
  A.nzmax = static_cast<std::size_t>(row_ptr[n]);
  A.p = const_cast<long*>(row_ptr);
  A.i = const_cast<long*>(cols);
  A.nz = nullptr;
  A.x = const_cast<double*>(values);
  A.z = nullptr;
  A.stype = 1;
  A.itype = CHOLMOD_LONG;
  A.xtype = values ? CHOLMOD_REAL : CHOLMOD_PATTERN;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}

// One column of n values (CHOLMOD only reads a right-hand side).
inline cholmod_dense column_view(const double* x, long n) {
  cholmod_dense B;
  B.nrow = B.nzmax = B.d = static_cast<std::size_t>(n);
  B.ncol = 1;
  B.x = const_cast<double*>(x);
  B.z = nullptr;
  B.xtype = CHOLMOD_REAL;
  B.dtype = CHOLMOD_DOUBLE;
  return B;
}

// The permuted lower triangle (stype = -1) over its arrays.
cholmod_sparse lower_csc_view(PermutedLower& a);

// Symbolic analysis of the permuted lower triangle with the natural ordering and no postordering
// (its permutation already has both), supernodal. nullptr on failure, or when CHOLMOD chose
// another order (the factorisation would then permute again).
cholmod_factor* analyse_as_ordered(PermutedLower& a, cholmod_common* common);

}  // namespace spifit::solver
