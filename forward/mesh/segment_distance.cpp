#include "forward/mesh/segment_distance.hpp"

#include <algorithm>
#include <cmath>

namespace spifit::mesh {
namespace {

double point_rectangle_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  const Eigen::Vector2d nearest = p.cwiseMax(lo).cwiseMin(hi);
  return (p - nearest).norm();
}

double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Liang-Barsky: does the segment a-b cross the rectangle?
bool segment_meets_rectangle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  double t0 = 0.0, t1 = 1.0;
  const Eigen::Vector2d d = b - a;
  for (int k = 0; k < 2; ++k) {
    if (d(k) == 0.0) {
      if (a(k) < lo(k) || a(k) > hi(k)) return false;
      continue;
    }
    double ta = (lo(k) - a(k)) / d(k), tb = (hi(k) - a(k)) / d(k);
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

double rectangle_segment_distance(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  if (segment_meets_rectangle(a, b, lo, hi)) return 0.0;
  // Apart, two convex sets are closest at a vertex of one of them.
  double d = std::min(point_rectangle_distance(a, lo, hi), point_rectangle_distance(b, lo, hi));
  for (const Eigen::Vector2d& c : {lo, Eigen::Vector2d(hi.x(), lo.y()), hi, Eigen::Vector2d(lo.x(), hi.y())})
    d = std::min(d, point_segment_distance(c, a, b));
  return d;
}

}  // namespace spifit::mesh
