#pragma once
// The load factor of a tool scene and the tool's travel along its path. The Newton solver steps
// the load factor lambda in [0, 1]; the tool sits at travel(lambda) mm along the path. The map
// is piecewise linear on increasing knots: linear(L) is travel = lambda L; a cone shortens the
// horizontal moves of a pie between contours, where the tool is in the air
// (cone/cone_load_map.hpp). effective_length() is the mm of "load" the map spans: an increment
// of travel_per_increment mm is travel_per_increment / effective_length() of the load factor.
#include <vector>

namespace spifit::scene {

class LoadMap {
 public:
  LoadMap() = default;
  // travel = lambda x length.
  static LoadMap linear(double length);
  // Knots (strictly increasing, lambda from 0 to 1, travel from 0 to the path length).
  LoadMap(std::vector<double> lambda_knots, std::vector<double> travel_knots, double effective_length);
  double travel(double lambda) const;  // mm along the path, lambda clamped to [0, 1]
  double lambda(double travel) const;  // inverse, travel clamped to [0, path length]
  double effective_length() const { return effective_length_; }
  double length() const { return travel_.empty() ? 0.0 : travel_.back(); }

 private:
  std::vector<double> lambda_, travel_;
  double effective_length_ = 0.0;
};

}  // namespace spifit::scene
