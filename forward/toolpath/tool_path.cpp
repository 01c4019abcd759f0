#include "forward/toolpath/tool_path.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace spifit::toolpath {

ToolPath::ToolPath(std::vector<Waypoint> points, double rapid_feed)
    : waypoints_(std::move(points)), rapid_feed_(rapid_feed) {
  if (waypoints_.size() < 2) throw std::invalid_argument("tool path needs at least 2 waypoints");
  if (!std::isfinite(rapid_feed_) || rapid_feed_ <= 0.0)
    throw std::invalid_argument("tool path rapid feed must be > 0");
  for (std::size_t i = 0; i < waypoints_.size(); ++i) {
    const Waypoint& w = waypoints_[i];
    if (!w.position.allFinite())
      throw std::invalid_argument("tool path waypoint " + std::to_string(i) + " is not finite");
    if (!std::isfinite(w.feed) || w.feed < 0.0)
      throw std::invalid_argument("tool path waypoint " + std::to_string(i) +
                                  " has a negative or non-finite feed");
  }
  // Prefix sums once, so that the queries are binary searches. A zero-length segment adds
  // nothing to either sum (no division by its length anywhere).
  cumulative_distance_.assign(waypoints_.size(), 0.0);
  cumulative_time_.assign(waypoints_.size(), 0.0);
  for (std::size_t i = 1; i < waypoints_.size(); ++i) {
    const double l = (waypoints_[i].position - waypoints_[i - 1].position).norm();
    cumulative_distance_[i] = cumulative_distance_[i - 1] + l;
    cumulative_time_[i] = cumulative_time_[i - 1] + l / segment_speed(i);
  }
}

ToolPath ToolPath::from_points(const std::vector<Eigen::Vector3d>& p, double feed) {
  std::vector<Waypoint> w;
  w.reserve(p.size());
  for (const auto& x : p) w.push_back(Waypoint{x, feed, 0});
  return ToolPath(std::move(w));
}

double ToolPath::segment_speed(std::size_t i) const {
  const double f = waypoints_[i].feed;
  return f > 0.0 ? f : rapid_feed_;
}

Eigen::Vector3d ToolPath::at_distance(double s) const {
  if (!(s > 0.0)) return waypoints_.front().position;  // also NaN
  if (s >= length()) return waypoints_.back().position;
  // First waypoint strictly beyond s: cumulative_distance_[i-1] <= s < cumulative_distance_[i],
  // so segment i has positive length (zero-length segments are never selected).
  const auto it = std::upper_bound(cumulative_distance_.begin(), cumulative_distance_.end(), s);
  const auto i = static_cast<std::size_t>(it - cumulative_distance_.begin());
  const double s0 = cumulative_distance_[i - 1], s1 = cumulative_distance_[i];
  const double a = (s - s0) / (s1 - s0);
  return (1.0 - a) * waypoints_[i - 1].position + a * waypoints_[i].position;
}

double ToolPath::distance_at_time(double t) const {
  if (!(t > 0.0)) return 0.0;
  if (t >= duration()) return length();
  const auto it = std::upper_bound(cumulative_time_.begin(), cumulative_time_.end(), t);
  const auto i = static_cast<std::size_t>(it - cumulative_time_.begin());
  const double s = cumulative_distance_[i - 1] + (t - cumulative_time_[i - 1]) * segment_speed(i);
  return std::min(s, cumulative_distance_[i]);  // round-off must not pass the segment end
}

Eigen::Vector3d ToolPath::at_time(double t) const { return at_distance(distance_at_time(t)); }

ToolPath ToolPath::translated(const Eigen::Vector3d& offset) const {
  std::vector<Waypoint> w = waypoints_;
  for (auto& p : w) p.position += offset;
  return ToolPath(std::move(w), rapid_feed_);
}

}  // namespace spifit::toolpath
