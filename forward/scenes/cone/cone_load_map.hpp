#pragma once
// The load map of a cone run (common/load_map.hpp; docs/design/decisions.md): linear in the
// tool's travel with slope effective_length(), except on the horizontal moves of a pie between
// contours. The tool is in the air there, so each move is shortened to move_increments x
// travel_per_increment of "load" and crossed in that many increments instead of one per
// travel_per_increment mm (43 of the 121 increments of a cone70 contour on the coarse pie).
// breakpoints are the load factors where a shortened move starts and ends: no increment steps
// over one, so an increment never carries the tool from contact through the air back into contact.
#include "forward/scenes/common/load_map.hpp"
#include "forward/toolpath/cone_path.hpp"

#include <vector>

namespace spifit::scene {

struct ConeLoadMap {
  LoadMap map;
  std::vector<double> breakpoints;
  int shortened_moves = 0;
};

// move_increments = 0: no shortening (travel = lambda x path length, no breakpoints).
ConeLoadMap cone_load_map(const toolpath::ConePath& path, double travel_per_increment, int move_increments);

}  // namespace spifit::scene
