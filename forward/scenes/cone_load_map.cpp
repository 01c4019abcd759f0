#include "forward/scenes/cone_load_map.hpp"

#include <algorithm>
#include <stdexcept>

namespace spifit::scene {
namespace {

// Linear interpolation on strictly increasing knots x -> y, clamped at the ends.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double v) {
  if (v <= x.front()) return y.front();
  if (v >= x.back()) return y.back();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), v) - x.begin());  // x[i-1] <= v < x[i]
  return y[i - 1] + (v - x[i - 1]) / (x[i] - x[i - 1]) * (y[i] - y[i - 1]);
}

}  // namespace

ConeLoadMap::ConeLoadMap(const toolpath::ConePath& path, double travel_per_increment, int move_increments) {
  if (!(travel_per_increment > 0.0)) throw std::invalid_argument("ConeLoadMap: travel_per_increment must be > 0");
  if (move_increments < 0) throw std::invalid_argument("ConeLoadMap: move_increments must be >= 0");
  const std::vector<double> d = path.path.waypoint_distances();
  const double length = d.back();
  if (!(length > 0.0)) throw std::invalid_argument("ConeLoadMap: the path has no length");
  std::vector<double> effective{0.0};  // cumulative load at each knot
  std::vector<char> move_end{0};       // the knot ends a shortened move
  travel_ = {0.0};
  for (std::size_t i = 1; i < d.size(); ++i) {
    const double len = d[i] - d[i - 1];
    if (!(len > 0.0)) continue;  // repeated waypoint
    const bool shorten = move_increments > 0 && path.segments[i].move == toolpath::ConeMove::move &&
                         len > move_increments * travel_per_increment;
    effective.push_back(effective.back() + (shorten ? move_increments * travel_per_increment : len));
    travel_.push_back(d[i]);
    move_end.push_back(shorten ? 1 : 0);
    if (shorten) ++shortened_moves_;
  }
  effective_length_ = effective.back();
  lambda_.resize(effective.size());
  for (std::size_t i = 0; i < effective.size(); ++i) lambda_[i] = effective[i] / effective_length_;
  lambda_.back() = 1.0;
  travel_.back() = length;
  if (shortened_moves_ == 0) {  // exactly travel = lambda x length
    travel_ = {0.0, length};
    lambda_ = {0.0, 1.0};
    return;
  }
  for (std::size_t i = 1; i < move_end.size(); ++i) {
    if (!move_end[i]) continue;
    if (breakpoints_.empty() || breakpoints_.back() < lambda_[i - 1]) breakpoints_.push_back(lambda_[i - 1]);
    breakpoints_.push_back(lambda_[i]);
  }
}

double ConeLoadMap::travel(double lambda) const { return interpolate(lambda_, travel_, lambda); }

double ConeLoadMap::lambda(double travel) const { return interpolate(travel_, lambda_, travel); }

}  // namespace spifit::scene
