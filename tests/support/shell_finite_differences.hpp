#pragma once
// Central differences of a ShellQ4's residual with respect to its 24 DOFs: translations added,
// rotations applied to the directors exactly as the solver does (shared by the element tests).
#include "forward/element/director.hpp"
#include "forward/element/shell_q4.hpp"

#include <gtest/gtest.h>

namespace spifit::element::test {

inline Mat24 fd_tangent(ShellQ4& el, const NodeVectors& x, const NodeVectors& d, double h) {
  Mat24 k;
  for (int j = 0; j < 24; ++j) {
    const std::size_t node = static_cast<std::size_t>(j / 6);
    const int c = j % 6;
    Vec24 r[2];
    for (int s = 0; s < 2; ++s) {
      NodeVectors xp = x, dp = d;
      const double step = s == 0 ? h : -h;
      if (c < 3) xp[node](c) += step;
      else dp[node] = rotate_by_vector(d[node], step * Eigen::Vector3d::Unit(c - 3));
      EXPECT_TRUE(el.compute(xp, dp, &r[s], nullptr).ok);
    }
    k.col(j) = (r[0] - r[1]) / (2.0 * h);
  }
  return k;
}

}  // namespace spifit::element::test
