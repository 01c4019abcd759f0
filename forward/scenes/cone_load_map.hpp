#pragma once
// The load factor of a cone run and the tool's travel along its path (docs/cone-scene.md,
// "Speed"). The Newton solver steps the load factor lambda in [0, 1]; the tool sits at
// travel(lambda) on the path. Everywhere the map is linear with slope effective_length(),
// except on the horizontal moves of a pie between contours: the tool is in the air there, so
// each move is shortened to move_increments x travel_per_increment of "load" and crossed in
// that many increments instead of one per travel_per_increment mm (43 of the 121 increments
// of a cone70 contour on the coarse pie). breakpoints() are the load factors where a move
// starts and ends: no increment steps over one, so an increment never carries the tool from
// contact through the air back into contact.
#include "forward/toolpath/cone_path.hpp"

#include <vector>

namespace spifit::scene {

class ConeLoadMap {
 public:
  // move_increments = 0: no shortening (travel = lambda x path length, no breakpoints).
  ConeLoadMap(const toolpath::ConePath& path, double travel_per_increment, int move_increments);
  double travel(double lambda) const;  // mm along the path, lambda clamped to [0, 1]
  double lambda(double travel) const;  // inverse, travel clamped to [0, path length]
  double effective_length() const { return effective_length_; }  // mm of load: one increment = travel_per_increment of it
  const std::vector<double>& breakpoints() const { return breakpoints_; }
  int shortened_moves() const { return shortened_moves_; }

 private:
  std::vector<double> travel_, lambda_;  // knots, both strictly increasing
  std::vector<double> breakpoints_;
  double effective_length_ = 0.0;
  int shortened_moves_ = 0;
};

}  // namespace spifit::scene
