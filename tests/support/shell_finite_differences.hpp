#pragma once
// Central differences of a ShellQ4's residual with respect to its 24 DOFs: translations added,
// rotations applied to the directors exactly as the solver does (shared by the element tests).
#include "forward/element/director.hpp"
#include "forward/element/shell_q4.hpp"

#include <gtest/gtest.h>

namespace spifit::element::test {

// (x, d) moved by step along DOF j (node j / 6; translation, or rotation of its director).
inline void perturb(int j, double step, NodeVectors* x, NodeVectors* d) {
  const std::size_t node = static_cast<std::size_t>(j / 6);
  const int c = j % 6;
  if (c < 3) (*x)[node](c) += step;
  else (*d)[node] = rotate_by_vector((*d)[node], step * Eigen::Vector3d::Unit(c - 3));
}

inline Mat24 fd_tangent(ShellQ4& el, const NodeVectors& x, const NodeVectors& d, double h) {
  Mat24 k;
  for (int j = 0; j < 24; ++j) {
    Vec24 r[2];
    for (int s = 0; s < 2; ++s) {
      NodeVectors xp = x, dp = d;
      perturb(j, s == 0 ? h : -h, &xp, &dp);
      EXPECT_TRUE(el.compute(xp, dp, &r[s], nullptr).ok);
    }
    k.col(j) = (r[0] - r[1]) / (2.0 * h);
  }
  return k;
}

}  // namespace spifit::element::test
