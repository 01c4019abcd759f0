#pragma once
// The path of the forming tool CENTRE (not the contact point) as a polyline of waypoints, with
// a feed per segment. Readers: G-code (gcode.hpp) and CSV point lists (path_csv.hpp). Units
// mm and s (docs/reference/file-formats.md). Queries by travelled distance or by time clamp to the path ends.
#include <Eigen/Core>

#include <vector>

namespace spifit::toolpath {

struct Waypoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // tool centre, mm
  double feed = 0.0;    // mm/s used to reach this point from the previous one; 0 = rapid
  int source_line = 0;  // 1-based line in the input file that produced the point; 0 = none
};

class ToolPath {
 public:
  // Segment i runs from waypoint i-1 to waypoint i at waypoint i's feed (the first waypoint's
  // feed is not used); rapid segments (feed 0) run at rapid_feed. Zero-length segments are
  // allowed and take no time. Throws std::invalid_argument on fewer than 2 points, non-finite
  // coordinates or feeds, a negative feed, or rapid_feed <= 0 (readers check their input
  // first and report file and line).
  explicit ToolPath(std::vector<Waypoint> points, double rapid_feed = 100.0);

  // All points at the same feed (mm/s, > 0 for a fed path, 0 for rapids).
  static ToolPath from_points(const std::vector<Eigen::Vector3d>& p, double feed);

  double length() const { return cumulative_distance_.back(); }  // total travel, mm
  double duration() const { return cumulative_time_.back(); }    // s
  double rapid_feed() const { return rapid_feed_; }              // mm/s

  // Point at travelled distance s, clamped to [0, length()]; linear inside a segment.
  Eigen::Vector3d at_distance(double s) const;
  // Point reached at time t, clamped to [0, duration()].
  Eigen::Vector3d at_time(double t) const;
  // Travelled distance at time t, clamped to [0, duration()].
  double distance_at_time(double t) const;

  // Cumulative distance at each waypoint (first 0, last length()); one entry per waypoint.
  std::vector<double> waypoint_distances() const { return cumulative_distance_; }
  const std::vector<Waypoint>& waypoints() const { return waypoints_; }

  // The same path shifted by offset (feeds, source lines, rapid feed unchanged).
  ToolPath translated(const Eigen::Vector3d& offset) const;

 private:
  double segment_speed(std::size_t i) const;  // mm/s of segment i (ending at waypoint i)

  std::vector<Waypoint> waypoints_;
  double rapid_feed_;
  std::vector<double> cumulative_distance_;  // per waypoint
  std::vector<double> cumulative_time_;      // per waypoint
};

}  // namespace spifit::toolpath
