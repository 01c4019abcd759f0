#include "forward/solver/permuted_lower.hpp"

#include "forward/solver/cholmod_views.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace spifit::solver {

cholmod_sparse lower_csc_view(PermutedLower& a) {
  cholmod_sparse A;
  A.nrow = A.ncol = static_cast<std::size_t>(a.n);
  A.nzmax = a.idx.size();
  A.p = a.ptr.data();
  A.i = a.idx.data();
  A.nz = nullptr;
  A.x = a.values.data();
  A.z = nullptr;
  A.stype = -1;
  A.itype = CHOLMOD_LONG;
  A.xtype = CHOLMOD_REAL;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}

Eigen::VectorXd PermutedLower::to_pivots(const double* b) const {
  Eigen::VectorXd y(n);
  for (long k = 0; k < n; ++k) y(k) = b[perm[static_cast<std::size_t>(k)]];
  return y;
}

void PermutedLower::from_pivots(const double* y, double* x) const {
  for (long k = 0; k < n; ++k) x[perm[static_cast<std::size_t>(k)]] = y[k];
}

PermutedLower permuted_lower(long n, const long* row_ptr, const long* cols, const long* value_of, const long* perm) {
  PermutedLower out;
  out.n = n;
  out.perm.assign(perm, perm + n);
  std::vector<long> pivot(static_cast<std::size_t>(n));
  for (long k = 0; k < n; ++k) pivot[static_cast<std::size_t>(perm[k])] = k;
  // (column, row, source) of every kept entry, then sorted into compressed columns.
  std::vector<std::pair<std::pair<long, long>, long>> entries;
  entries.reserve(static_cast<std::size_t>(row_ptr[n] / 2 + n));
  for (long r = 0; r < n; ++r)
    for (long k = row_ptr[r]; k < row_ptr[r + 1]; ++k) {
      const long c = cols[k];
      if (c > r) continue;
      const long a = pivot[static_cast<std::size_t>(r)], b = pivot[static_cast<std::size_t>(c)];
      entries.push_back({{std::min(a, b), std::max(a, b)}, value_of ? value_of[k] : k});
    }
  std::sort(entries.begin(), entries.end());
  out.ptr.assign(static_cast<std::size_t>(n) + 1, 0);
  out.idx.reserve(entries.size());
  out.source.reserve(entries.size());
  for (const auto& [at, src] : entries) {
    ++out.ptr[static_cast<std::size_t>(at.first) + 1];
    out.idx.push_back(at.second);
    out.source.push_back(src);
  }
  std::partial_sum(out.ptr.begin(), out.ptr.end(), out.ptr.begin());
  out.values.assign(out.idx.size(), 0.0);
  return out;
}

cholmod_factor* analyse_as_ordered(PermutedLower& a, cholmod_common* common) {
  const int nmethods = common->nmethods, ordering = common->method[0].ordering, postorder = common->postorder;
  common->nmethods = 1;
  common->method[0].ordering = CHOLMOD_NATURAL;
  common->postorder = 0;
  cholmod_sparse A = lower_csc_view(a);
  cholmod_factor* f = cholmod_l_analyze(&A, common);
  common->nmethods = nmethods;
  common->method[0].ordering = ordering;
  common->postorder = postorder;
  if (f && f->ordering != CHOLMOD_NATURAL) cholmod_l_free_factor(&f, common);
  return f;
}

}  // namespace spifit::solver
