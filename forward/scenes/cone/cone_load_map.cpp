#include "forward/scenes/cone/cone_load_map.hpp"

#include <stdexcept>

namespace spifit::scene {

ConeLoadMap cone_load_map(const toolpath::ConePath& path, double travel_per_increment, int move_increments) {
  if (!(travel_per_increment > 0.0)) throw std::invalid_argument("cone load map: travel_per_increment must be > 0");
  if (move_increments < 0) throw std::invalid_argument("cone load map: move_increments must be >= 0");
  const std::vector<double> d = path.path.waypoint_distances();
  const double length = d.back();
  if (!(length > 0.0)) throw std::invalid_argument("cone load map: the path has no length");
  ConeLoadMap out;
  std::vector<double> effective{0.0};  // cumulative load at each knot
  std::vector<char> move_end{0};       // the knot ends a shortened move
  std::vector<double> travel{0.0};
  for (std::size_t i = 1; i < d.size(); ++i) {
    const double len = d[i] - d[i - 1];
    if (!(len > 0.0)) continue;  // repeated waypoint
    const bool shorten = move_increments > 0 && path.segments[i].move == toolpath::ConeMove::move &&
                         len > move_increments * travel_per_increment;
    effective.push_back(effective.back() + (shorten ? move_increments * travel_per_increment : len));
    travel.push_back(d[i]);
    move_end.push_back(shorten ? 1 : 0);
    if (shorten) ++out.shortened_moves;
  }
  const double effective_length = effective.back();
  if (out.shortened_moves == 0) {  // exactly travel = lambda x length
    out.map = LoadMap({0.0, 1.0}, {0.0, length}, effective_length);
    return out;
  }
  std::vector<double> lambda(effective.size());
  for (std::size_t i = 0; i < effective.size(); ++i) lambda[i] = effective[i] / effective_length;
  lambda.back() = 1.0;
  travel.back() = length;
  for (std::size_t i = 1; i < move_end.size(); ++i) {
    if (!move_end[i]) continue;
    if (out.breakpoints.empty() || out.breakpoints.back() < lambda[i - 1]) out.breakpoints.push_back(lambda[i - 1]);
    out.breakpoints.push_back(lambda[i]);
  }
  out.map = LoadMap(std::move(lambda), std::move(travel), effective_length);
  return out;
}

}  // namespace spifit::scene
