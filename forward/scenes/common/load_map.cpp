#include "forward/scenes/common/load_map.hpp"

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

LoadMap LoadMap::linear(double length) { return LoadMap({0.0, 1.0}, {0.0, length}, length); }

LoadMap::LoadMap(std::vector<double> lambda_knots, std::vector<double> travel_knots, double effective_length)
    : lambda_(std::move(lambda_knots)), travel_(std::move(travel_knots)), effective_length_(effective_length) {
  if (lambda_.size() < 2 || lambda_.size() != travel_.size()) throw std::invalid_argument("LoadMap: needs two or more knots of each");
  for (std::size_t i = 1; i < lambda_.size(); ++i)
    if (!(lambda_[i] > lambda_[i - 1]) || !(travel_[i] > travel_[i - 1])) throw std::invalid_argument("LoadMap: knots must increase");
  if (!(effective_length_ > 0.0)) throw std::invalid_argument("LoadMap: the path has no length");
}

double LoadMap::travel(double lambda) const { return interpolate(lambda_, travel_, lambda); }

double LoadMap::lambda(double travel) const { return interpolate(travel_, lambda_, travel); }

}  // namespace spifit::scene
