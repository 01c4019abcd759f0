// ToolPath: length, duration, queries by distance and time on a path with a rapid segment,
// clamping, zero-length segments, waypoint distances, translation, argument checks.
#include "forward/toolpath/tool_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace spifit::toolpath;

namespace {

void expect_point(const Eigen::Vector3d& p, double x, double y, double z, double tol = 1e-12) {
  EXPECT_NEAR(p.x(), x, tol);
  EXPECT_NEAR(p.y(), y, tol);
  EXPECT_NEAR(p.z(), z, tol);
}

// A (0,0,0) -rapid-> B (3,4,0) -2 mm/s-> C (3,4,-6) -4 mm/s-> D (11,4,-6), rapid feed 100 mm/s:
// lengths 5, 6, 8 (total 19); times 0.05, 3, 2 (total 5.05).
ToolPath three_segments() {
  return ToolPath({Waypoint{{0, 0, 0}, 0.0, 1}, Waypoint{{3, 4, 0}, 0.0, 2},
                   Waypoint{{3, 4, -6}, 2.0, 3}, Waypoint{{11, 4, -6}, 4.0, 4}},
                  100.0);
}

}  // namespace

TEST(ToolPath, LengthAndDurationWithRapidSegment) {
  const ToolPath p = three_segments();
  EXPECT_NEAR(p.length(), 19.0, 1e-12);
  EXPECT_NEAR(p.duration(), 0.05 + 3.0 + 2.0, 1e-12);
  EXPECT_EQ(p.rapid_feed(), 100.0);
  EXPECT_EQ(p.waypoints().size(), 4u);
  EXPECT_EQ(p.waypoints()[2].source_line, 3);
}

TEST(ToolPath, AtDistanceIsLinearInsideSegments) {
  const ToolPath p = three_segments();
  expect_point(p.at_distance(0.0), 0, 0, 0);
  expect_point(p.at_distance(2.5), 1.5, 2.0, 0.0);
  expect_point(p.at_distance(5.0), 3, 4, 0);
  expect_point(p.at_distance(8.0), 3, 4, -3);
  expect_point(p.at_distance(15.0), 7, 4, -6);
  expect_point(p.at_distance(19.0), 11, 4, -6);
}

TEST(ToolPath, AtTimeUsesSegmentFeeds) {
  const ToolPath p = three_segments();
  expect_point(p.at_time(0.025), 1.5, 2.0, 0.0);              // halfway through the rapid
  EXPECT_NEAR(p.distance_at_time(0.05), 5.0, 1e-12);          // end of the rapid
  expect_point(p.at_time(0.05 + 1.5), 3, 4, -3);              // 3 mm at 2 mm/s
  EXPECT_NEAR(p.distance_at_time(0.05 + 3.0 + 1.0), 15.0, 1e-12);  // 4 mm at 4 mm/s
  expect_point(p.at_time(0.05 + 3.0 + 1.0), 7, 4, -6);
  EXPECT_NEAR(p.distance_at_time(p.duration()), 19.0, 1e-12);
}

TEST(ToolPath, QueriesClampToThePathEnds) {
  const ToolPath p = three_segments();
  expect_point(p.at_distance(-3.0), 0, 0, 0);
  expect_point(p.at_distance(1e9), 11, 4, -6);
  expect_point(p.at_time(-1.0), 0, 0, 0);
  expect_point(p.at_time(1e9), 11, 4, -6);
  EXPECT_EQ(p.distance_at_time(-1.0), 0.0);
  EXPECT_EQ(p.distance_at_time(1e9), 19.0);
  expect_point(p.at_distance(std::numeric_limits<double>::quiet_NaN()), 0, 0, 0);
}

TEST(ToolPath, ZeroLengthSegmentTakesNoTimeAndNoDistance) {
  // A -> B -> B (repeated point) -> C at 2 mm/s: lengths 5, 0, 6.
  const ToolPath p({Waypoint{{0, 0, 0}, 0.0}, Waypoint{{3, 4, 0}, 2.0}, Waypoint{{3, 4, 0}, 2.0},
                    Waypoint{{3, 4, -6}, 2.0}});
  EXPECT_NEAR(p.length(), 11.0, 1e-12);
  EXPECT_NEAR(p.duration(), 5.5, 1e-12);
  const auto d = p.waypoint_distances();
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0], 0.0);
  EXPECT_NEAR(d[1], 5.0, 1e-12);
  EXPECT_NEAR(d[2], 5.0, 1e-12);
  EXPECT_NEAR(d[3], 11.0, 1e-12);
  expect_point(p.at_distance(5.0), 3, 4, 0);
  expect_point(p.at_distance(5.5), 3, 4, -0.5);
  expect_point(p.at_time(2.5), 3, 4, 0);
  expect_point(p.at_time(2.75), 3, 4, -0.5);
  for (double t = 0.0; t <= 6.0; t += 0.125) EXPECT_TRUE(p.at_time(t).allFinite()) << t;

  // Only zero-length segments: length and duration 0, every query gives the point.
  const ToolPath still = ToolPath::from_points({{1, 2, 3}, {1, 2, 3}}, 5.0);
  EXPECT_EQ(still.length(), 0.0);
  EXPECT_EQ(still.duration(), 0.0);
  expect_point(still.at_time(1.0), 1, 2, 3);
  expect_point(still.at_distance(0.5), 1, 2, 3);
}

TEST(ToolPath, WaypointDistancesAreCumulative) {
  const auto d = three_segments().waypoint_distances();
  ASSERT_EQ(d.size(), 4u);
  EXPECT_NEAR(d[0], 0.0, 1e-15);
  EXPECT_NEAR(d[1], 5.0, 1e-12);
  EXPECT_NEAR(d[2], 11.0, 1e-12);
  EXPECT_NEAR(d[3], 19.0, 1e-12);
}

TEST(ToolPath, FromPointsAndTranslated) {
  const ToolPath p = ToolPath::from_points({{0, 0, 0}, {10, 0, 0}, {10, 5, 0}}, 5.0);
  EXPECT_NEAR(p.length(), 15.0, 1e-12);
  EXPECT_NEAR(p.duration(), 3.0, 1e-12);
  const ToolPath q = p.translated({1, 2, -3});
  ASSERT_EQ(q.waypoints().size(), 3u);
  expect_point(q.waypoints()[2].position, 11, 7, -3);
  EXPECT_EQ(q.waypoints()[2].feed, 5.0);
  EXPECT_NEAR(q.length(), 15.0, 1e-12);
  EXPECT_NEAR(q.duration(), 3.0, 1e-12);
}

TEST(ToolPath, RejectsMeaninglessArguments) {
  const Eigen::Vector3d o = Eigen::Vector3d::Zero(), x(1, 0, 0);
  EXPECT_THROW(ToolPath({Waypoint{o, 1.0}}), std::invalid_argument);
  EXPECT_THROW(ToolPath({}), std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(ToolPath({Waypoint{o, 1.0}, Waypoint{{nan, 0, 0}, 1.0}}), std::invalid_argument);
  EXPECT_THROW(ToolPath({Waypoint{o, 1.0}, Waypoint{x, -1.0}}), std::invalid_argument);
  EXPECT_THROW(ToolPath({Waypoint{o, 1.0}, Waypoint{x, 1.0}}, 0.0), std::invalid_argument);
  EXPECT_THROW(ToolPath({Waypoint{o, 1.0}, Waypoint{x, 1.0}}, -5.0), std::invalid_argument);
  EXPECT_NO_THROW(ToolPath({Waypoint{o, 0.0}, Waypoint{x, 0.0}}));
}
