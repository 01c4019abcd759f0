#pragma once
// A symmetric matrix handed to CHOLMOD already permuted (docs/design/numerics-shell.md, "Sparse
// linear algebra"). CHOLMOD's supernodal factorisation works on the lower triangle of P A P^T;
// given A and a fill-reducing P it builds that matrix with a permuted transpose at every
// factorisation (line_half's linear solver: 10.15 s with it, 8.89 s without, medians of 3). Here
// the pattern of the permuted lower triangle and the position of each of its values in A are
// worked out once per pattern; each factorisation gathers the values into it, and CHOLMOD,
// analysing it with the natural ordering, factorises it as it is. The factor is the one CHOLMOD
// would have made from A and P, bit for bit: the same values in the same places.
#include <Eigen/Core>

#include <vector>

namespace spifit::solver {

struct PermutedLower {
  long n = 0;
  std::vector<long> ptr, idx;  // compressed columns, rows sorted within each column
  std::vector<long> source;    // value k = value source[k] of A's arrays
  std::vector<long> perm;      // pivot k is unknown perm[k] of A
  std::vector<double> values;

  void gather(const double* a) {
    for (std::size_t k = 0; k < source.size(); ++k) values[k] = a[source[k]];
  }
  // b in A's order -> P b; and back.
  Eigen::VectorXd to_pivots(const double* b) const;
  void from_pivots(const double* y, double* x) const;
};

// CHOLMOD's side (its header, the analysis) is in cholmod_views.hpp.
//
// A: n x n, both triangles in CSR (row_ptr, cols, columns sorted), symmetric; each pair is taken
// from its entry (r, c) with c <= r, the triangle CHOLMOD reads when given the CSR arrays as
// columns with stype = 1. value_of[k] (nullptr: k itself) is the position of A's value k in the
// array gather() reads. perm: CHOLMOD's permutation (pivot k is unknown perm[k]).
PermutedLower permuted_lower(long n, const long* row_ptr, const long* cols, const long* value_of, const long* perm);

}  // namespace spifit::solver
