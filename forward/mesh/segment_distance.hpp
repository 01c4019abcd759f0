#pragma once
// The distance in the x-y plane between an axis-aligned rectangle (a sheet's cell) and a segment
// (a piece of the tool path): what a coarsened sheet keeps fine (square_sheet.hpp).
#include <Eigen/Core>

namespace spifit::mesh {

// Distance in x-y between the rectangle [lo, hi] and the segment a-b; 0 when they meet.
double rectangle_segment_distance(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

}  // namespace spifit::mesh
