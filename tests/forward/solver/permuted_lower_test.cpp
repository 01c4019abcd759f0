// The permuted lower triangle CHOLMOD is handed (permuted_lower.hpp): P A P^T entry by entry on a
// small symmetric matrix, each value taken from the triangle CHOLMOD read before (c <= r in CSR).
#include "forward/solver/permuted_lower.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace spifit::solver {
namespace {

TEST(PermutedLower, IsTheLowerTriangleOfThePermutedMatrixWithItsSources) {
  // A 4 x 4 symmetric pattern (both triangles in CSR); values = 10 r + c, so each stored entry
  // says where it came from (A itself is not symmetric in value: the test sees which triangle is read).
  const long n = 4;
  const std::vector<long> row_ptr = {0, 3, 5, 8, 10};
  const std::vector<long> cols = {0, 1, 2, 0, 1, 0, 2, 3, 2, 3};
  std::vector<double> a;
  for (long r = 0; r < n; ++r)
    for (long k = row_ptr[r]; k < row_ptr[r + 1]; ++k) a.push_back(10.0 * static_cast<double>(r) + static_cast<double>(cols[k]));
  const std::vector<long> perm = {2, 0, 3, 1};  // pivot k is unknown perm[k]
  PermutedLower p = permuted_lower(n, row_ptr.data(), cols.data(), nullptr, perm.data());
  p.gather(a.data());

  Eigen::MatrixXd got = Eigen::MatrixXd::Zero(n, n);
  for (long c = 0; c < n; ++c)
    for (long k = p.ptr[c]; k < p.ptr[c + 1]; ++k) {
      ASSERT_GE(p.idx[k], c) << "lower triangle only";
      if (k > p.ptr[c]) {
        EXPECT_LT(p.idx[k - 1], p.idx[k]) << "rows sorted within a column";
      }
      got(p.idx[k], c) = p.values[k];
    }
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(n, n);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j <= i; ++j) {
      const long r = std::max(perm[i], perm[j]), c = std::min(perm[i], perm[j]);  // the c <= r entry of A
      for (long k = row_ptr[r]; k < row_ptr[r + 1]; ++k)
        if (cols[k] == c) expected(i, j) = a[static_cast<std::size_t>(k)];
    }
  EXPECT_EQ(got, expected);
  EXPECT_EQ(p.idx.size(), 7u);  // the 4 diagonal entries and the 3 off-diagonal pairs

  // value_of redirects the sources (the split CHOLMOD's halves gather from the whole matrix).
  std::vector<long> shifted(cols.size());
  for (std::size_t k = 0; k < shifted.size(); ++k) shifted[k] = static_cast<long>(k) + 100;
  const PermutedLower q = permuted_lower(n, row_ptr.data(), cols.data(), shifted.data(), perm.data());
  for (std::size_t k = 0; k < q.source.size(); ++k) EXPECT_EQ(q.source[k], p.source[k] + 100);

  // Right-hand sides go to pivot order and back.
  const Eigen::Vector4d b(1.0, 2.0, 3.0, 4.0);
  const Eigen::VectorXd y = p.to_pivots(b.data());
  EXPECT_EQ(y, Eigen::Vector4d(3.0, 1.0, 4.0, 2.0));
  Eigen::Vector4d back;
  p.from_pivots(y.data(), back.data());
  EXPECT_EQ(back, b);
}

}  // namespace
}  // namespace spifit::solver
