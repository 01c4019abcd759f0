// Cone tool paths (thesis §8.1, §9.1): tool centre at R from the CAD surface point it touches,
// chord error, pie edges and lift/move/plunge, full-disc ramps and descent, one direction of
// travel, the cone70 numbers by hand, length against the analytic sum, the vwall stages, option
// checks.
#include "forward/toolpath/cone_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

using namespace spifit::toolpath;

namespace {

constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180.0; }
Eigen::Vector3d unit(double theta) { return {std::cos(theta), std::sin(theta), 0.0}; }
double radius(const Eigen::Vector3d& p) { return std::hypot(p.x(), p.y()); }
double angle(const Eigen::Vector3d& p) { return std::atan2(p.y(), p.x()); }
double horizontal(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::hypot(b.x() - a.x(), b.y() - a.y());
}
// z component of a x b (horizontal turning direction seen from +z).
double turn(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return a.x() * b.y() - a.y() * b.x();
}
// Angle of b - angle of a, wrapped to (-pi, pi].
double dtheta(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  double d = angle(b) - angle(a);
  while (d <= -kPi) d += 2.0 * kPi;
  while (d > kPi) d -= 2.0 * kPi;
  return d;
}

// Distance of the point (r, z) from the CAD line through (r_top, t/2) with downward direction
// (-cos a, -sin a), signed positive on the tool side (normal (-sin a, cos a)), and the depth
// below t/2 of the foot of the perpendicular (the touching point).
struct CadDistance {
  double normal, depth;
};
CadDistance cad_distance(const ConePathOptions& o, double r, double z) {
  const double a = rad(o.wall_angle_deg);
  const double vr = r - o.top_radius, vz = z - 0.5 * o.thickness;
  const double along = -vr * std::cos(a) - vz * std::sin(a);  // along the downward direction
  return {-vr * std::sin(a) + vz * std::cos(a), along * std::sin(a)};
}

// Every waypoint of the segments of one kind.
template <class F>
void for_each(const ConePath& p, ConeMove m, F f) {
  const auto& w = p.path.waypoints();
  for (std::size_t i = 1; i < w.size(); ++i)
    if (p.segments[i].move == m) f(i, w[i - 1].position, w[i].position, p.segments[i]);
}

std::string message_of(const ConePathOptions& o) {
  try {
    cone_path(o);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no exception";
}

}  // namespace

TEST(ConePath, CentreIsToolRadiusFromTheTouchingPoint) {
  for (const ConePathOptions& o : {cone70(60, 45.0), cone70(60, 360.0), cone50(90.0)}) {
    const ConePath p = annotated_cone_path(o);
    const double a = rad(o.wall_angle_deg);
    int count = 0;
    for_each(p, ConeMove::contour, [&](std::size_t, const Eigen::Vector3d&,
                                       const Eigen::Vector3d& x, const ConeSegment& s) {
      const CadDistance d = cad_distance(o, radius(x), x.z());
      EXPECT_NEAR(d.normal, o.tool_radius, 1e-9);
      EXPECT_NEAR(d.depth, s.contour * o.stepdown, 1e-9);
      // Tip R (1 - cos a) below the touching point.
      EXPECT_NEAR(x.z() - o.tool_radius,
                  0.5 * o.thickness - s.contour * o.stepdown - o.tool_radius * (1 - std::cos(a)),
                  1e-9);
      EXPECT_NEAR(radius(x), cone_contour_centre_radius(o, s.contour), 1e-9);
      EXPECT_NEAR(x.z(), cone_contour_centre_z(o, s.contour), 1e-12);
      ++count;
    });
    EXPECT_GT(count, 1000);
    // The ramps keep the tool on the CAD surface too.
    for_each(p, ConeMove::ramp, [&](std::size_t, const Eigen::Vector3d&, const Eigen::Vector3d& x,
                                    const ConeSegment&) {
      EXPECT_NEAR(cad_distance(o, radius(x), x.z()).normal, o.tool_radius, 1e-9);
    });
  }
}

TEST(ConePath, Cone70ByHand) {
  // r_c(1) = 90 - 0.5 / tan 70 - 5 sin 70 = 90 - 0.18198511 - 4.69846310;
  // z_c(1) = 0.6 - 0.5 + 5 cos 70 = 0.1 + 1.71010072.
  const ConePathOptions o = cone70(60, 45.0);
  EXPECT_NEAR(cone_contour_centre_radius(o, 1), 85.1195518, 1e-7);
  EXPECT_NEAR(cone_contour_centre_z(o, 1), 1.8101007, 1e-7);
  EXPECT_NEAR(cone_contour_touch_radius(o, 1), 90.0 - 0.5 / 2.7474774194546216, 1e-12);
  // Contour 60 touches the CAD surface 30 mm below the top surface: z = 0.6 - 30.
  EXPECT_NEAR(cone_contour_touch_z(o, 60), -29.4, 1e-12);
  EXPECT_NEAR(cone_contour_touch_radius(o, 60), 90.0 - 30.0 / 2.7474774194546216, 1e-12);
  EXPECT_NEAR(cone_contour_centre_z(o, 60), -29.4 + 1.7101007166, 1e-9);
  const ToolPath p = cone_path(o);
  double z_min = 1e9;
  for (const auto& w : p.waypoints()) z_min = std::min(z_min, w.position.z());
  EXPECT_NEAR(z_min, -29.4 + 1.7101007166, 1e-9);  // deepest centre: contour 60
  EXPECT_NEAR(z_min - 5.0, -29.4 - 5.0 * (1.0 - 0.3420201433), 1e-9);  // its tip
  EXPECT_EQ(cone70(100).contours, 100);
  EXPECT_NEAR(cone_contour_touch_z(cone70(100), 100), 0.6 - 50.0, 1e-12);
  // Start and end: tip 1 mm above the top surface.
  EXPECT_NEAR(p.waypoints().front().position.z(), 0.6 + 1.0 + 5.0, 1e-12);
  EXPECT_NEAR(p.waypoints().back().position.z(), 0.6 + 1.0 + 5.0, 1e-12);
}

TEST(ConePath, ChordsStayWithinTheTolerance) {
  for (const ConePathOptions& o : {cone70(60, 45.0), cone70(20, 360.0)}) {
    const ConePath p = annotated_cone_path(o);
    double worst = 0.0;
    for_each(p, ConeMove::contour, [&](std::size_t, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const ConeSegment& s) {
      const double r = cone_contour_centre_radius(o, s.contour);
      EXPECT_NEAR(radius(a), r, 1e-9);
      EXPECT_NEAR(radius(b), r, 1e-9);
      const double sagitta = r - radius(0.5 * (a + b));  // chord midpoint to circle
      EXPECT_LE(sagitta, o.chord_tolerance * (1 + 1e-9));
      worst = std::max(worst, sagitta);
    });
    EXPECT_GT(worst, 0.9 * o.chord_tolerance);  // not finer than needed
  }
}

TEST(ConePath, PieContoursRunEdgeToEdgeWithLiftMovePlunge) {
  for (const bool ccw : {true, false}) {
    ConePathOptions o = cone70(60, 45.0);
    o.counter_clockwise = ccw;
    const ConePath p = annotated_cone_path(o);
    const auto& w = p.path.waypoints();
    const double gamma = rad(45.0), sign = ccw ? 1.0 : -1.0;
    const double first = ccw ? 0.0 : gamma, last = ccw ? gamma : 0.0;
    int contours = 0, lifts = 0, moves = 0, plunges = 0;
    for (std::size_t i = 1; i < w.size(); ++i) {
      const ConeSegment& s = p.segments[i];
      const Eigen::Vector3d a = w[i - 1].position, b = w[i].position;
      EXPECT_EQ(w[i].feed, o.feed);
      switch (s.move) {
        case ConeMove::contour: {
          EXPECT_GE(angle(b), -1e-12);
          EXPECT_LE(angle(b), gamma + 1e-12);
          EXPECT_GT(sign * turn(a, b), 0.0);  // always the same direction
          if (p.segments[i - 1].move != ConeMove::contour) {  // first chord of a contour
            ++contours;
            EXPECT_EQ(s.contour, contours);
            EXPECT_NEAR(angle(a), first, 1e-12);
          }
          if (i + 1 == w.size() || p.segments[i + 1].move != ConeMove::contour) {
            EXPECT_NEAR(angle(b), last, 1e-12);
          }
          break;
        }
        case ConeMove::lift:
          ++lifts;
          EXPECT_EQ(p.segments[i - 1].move, ConeMove::contour);
          EXPECT_NEAR(horizontal(a, b), 0.0, 1e-12);
          EXPECT_NEAR(b.z() - a.z(), o.lift, 1e-12);
          break;
        case ConeMove::move:
          ++moves;
          EXPECT_EQ(p.segments[i - 1].move, ConeMove::lift);
          EXPECT_EQ(a.z(), b.z());
          EXPECT_NEAR(angle(b), first, 1e-12);
          EXPECT_NEAR(radius(b), cone_contour_centre_radius(o, s.contour), 1e-9);
          break;
        case ConeMove::plunge:
          ++plunges;
          EXPECT_EQ(p.segments[i - 1].move, ConeMove::move);
          EXPECT_NEAR(horizontal(a, b), 0.0, 1e-12);
          EXPECT_NEAR(a.z() - b.z(), o.lift + o.stepdown, 1e-12);
          EXPECT_EQ(p.segments[i + 1].move, ConeMove::contour);
          EXPECT_EQ(p.segments[i + 1].contour, s.contour);
          break;
        case ConeMove::approach:
        case ConeMove::retract:
          EXPECT_NEAR(horizontal(a, b), 0.0, 1e-12);
          break;
        default:
          ADD_FAILURE() << "unexpected move at waypoint " << i;
      }
    }
    EXPECT_EQ(contours, 60);
    EXPECT_EQ(lifts, 59);
    EXPECT_EQ(moves, 59);
    EXPECT_EQ(plunges, 59);
    EXPECT_EQ(p.segments.front().move, ConeMove::start);
    EXPECT_EQ(p.segments[1].move, ConeMove::approach);
    EXPECT_EQ(p.segments.back().move, ConeMove::retract);
  }
}

TEST(ConePath, FullDiscRampsDescendAtTheRampAngleAtTheStepdownLocation) {
  for (const bool ccw : {true, false}) {
    ConePathOptions o = cone50(360.0);  // stepdown at 6 deg, alpha 50, dz 1, 30 contours
    o.counter_clockwise = ccw;
    const ConePath p = annotated_cone_path(o);
    const auto& w = p.path.waypoints();
    const double sign = ccw ? 1.0 : -1.0, theta_s = rad(6.0), tan_ramp = std::tan(rad(10.0));
    // Ramps: every chord at 10 deg; the whole ramp k -> k+1 descends dz, moves in by
    // dz / tan 50 and sweeps cone_ramp_sweep(k) ~ sqrt(L^2 - dr^2) / r_mean, L = dz / tan 10.
    double ramp_descent = 0.0;
    std::vector<double> sweep(31, 0.0), drop(31, 0.0), dr(31, 0.0);
    for_each(p, ConeMove::ramp, [&](std::size_t i, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const ConeSegment& s) {
      // Chords are shorter than the arc by ~ tol / (3 r): slope error ~ 5e-6 rad.
      EXPECT_NEAR(std::atan2(a.z() - b.z(), horizontal(a, b)), rad(10.0), 1e-4);
      EXPECT_GT(sign * turn(a, b), 0.0);
      if (p.segments[i - 1].move != ConeMove::ramp) {  // every ramp starts at the stepdown angle
        EXPECT_NEAR(dtheta(unit(theta_s), a), 0.0, 1e-12);
      }
      sweep[s.contour] += sign * dtheta(a, b);
      drop[s.contour] += a.z() - b.z();
      dr[s.contour] += radius(b) - radius(a);
      ramp_descent += a.z() - b.z();
    });
    EXPECT_NEAR(ramp_descent, 29.0, 1e-9);
    for (int k = 2; k <= 30; ++k) {
      EXPECT_NEAR(drop[k], 1.0, 1e-12);
      EXPECT_NEAR(dr[k], -1.0 / std::tan(rad(50.0)), 1e-9);
      const double r_mean = cone_contour_centre_radius(o, k - 1) - 0.5 / std::tan(rad(50.0));
      const double l = 1.0 / tan_ramp;
      const double hand = std::sqrt(l * l - dr[k] * dr[k]) / r_mean;
      EXPECT_NEAR(sweep[k], cone_ramp_sweep(o, k - 1), 1e-9);
      EXPECT_NEAR(sweep[k], hand, 5e-5 * hand);  // exact: ln(1 + u) / u vs 1 / (1 + u / 2)
    }
    // Contours: contour 1 starts at the stepdown angle; every contour k >= 2 starts where the
    // ramp ends and, except the last, ends at the stepdown angle; contours 1 and N are full turns.
    std::vector<double> turned(31, 0.0);
    for_each(p, ConeMove::contour, [&](std::size_t i, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const ConeSegment& s) {
      EXPECT_GT(sign * turn(a, b), 0.0);  // always the same direction
      turned[s.contour] += sign * dtheta(a, b);
      if (p.segments[i - 1].move != ConeMove::contour) {
        const double start = s.contour == 1 ? theta_s : theta_s + sign * sweep[s.contour];
        EXPECT_NEAR(dtheta(unit(start), a), 0, 1e-12);
      }
      if (p.segments[i + 1].move != ConeMove::contour && s.contour < 30) {
        EXPECT_NEAR(dtheta(unit(theta_s), b), 0, 1e-12);
      }
    });
    EXPECT_NEAR(turned[1], 2 * kPi, 1e-9);
    EXPECT_NEAR(turned[30], 2 * kPi, 1e-9);
    for (int k = 2; k < 30; ++k) EXPECT_NEAR(turned[k], 2 * kPi - sweep[k], 1e-9);
    // Total descent: contour 1 touches dz below the top surface, contour N N dz.
    EXPECT_NEAR(0.5 * o.thickness - cone_contour_touch_z(o, 30), 30.0, 1e-12);
    EXPECT_NEAR(cone_contour_centre_z(o, 1) - cone_contour_centre_z(o, 30), 29.0, 1e-12);
    int starts = 0;
    for (std::size_t i = 1; i < w.size(); ++i)
      if (p.segments[i].move == ConeMove::contour && p.segments[i - 1].move != ConeMove::contour)
        ++starts;
    EXPECT_EQ(starts, 30);
  }
}

TEST(ConePath, LengthMatchesTheAnalyticSum) {
  for (const double pie : {45.0, 360.0}) {
    const ConePathOptions o = cone70(60, pie);
    const ConePath p = annotated_cone_path(o);
    const int n = 60;
    const double gamma = rad(pie), z_app = 0.6 + 1.0 + 5.0;
    double contours = 0.0, expected = 0.0;
    for (int k = 1; k <= n; ++k) {
      const double r = cone_contour_centre_radius(o, k);
      double arc = gamma * r;
      if (pie == 360.0 && k > 1 && k < n) arc -= cone_ramp_sweep(o, k - 1) * r;
      contours += arc;
      if (k == n) continue;
      if (pie == 360.0) {
        expected += o.stepdown / std::sin(rad(o.ramp_angle_deg));  // ramp (3-D length)
      } else {  // lift, straight horizontal move edge to edge, plunge
        const double r1 = cone_contour_centre_radius(o, k + 1);
        const double move = std::sqrt(r * r + r1 * r1 - 2 * r * r1 * std::cos(gamma));
        expected += o.lift + move + o.lift + o.stepdown;
      }
    }
    expected += contours + (z_app - cone_contour_centre_z(o, 1)) +  // approach
                (z_app - cone_contour_centre_z(o, n));                // retract
    double fed_contours = 0.0;
    for_each(p, ConeMove::contour, [&](std::size_t, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const ConeSegment&) {
      fed_contours += (b - a).norm();
    });
    EXPECT_NEAR(fed_contours / contours, 1.0, 1e-4) << pie;  // chords: deficit ~ tol / (3 r)
    EXPECT_NEAR(p.path.length() / expected, 1.0, 1e-3) << pie;
    EXPECT_NEAR(p.path.duration(), p.path.length() / (2000.0 / 60.0), 1e-9 * p.path.duration());
  }
}

TEST(ConePath, VwallStagesIncludingTheVerticalWall) {
  const auto stages = vwall_stages(360.0);
  ASSERT_EQ(stages.size(), 5u);
  const double angles[] = {50, 60, 70, 80, 90}, stepdowns[] = {6, -177, -118, 43, -45};
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(stages[i].wall_angle_deg, angles[i]);
    EXPECT_EQ(stages[i].stepdown_angle_deg, stepdowns[i]);
    EXPECT_EQ(stages[i].contours, 30);
    EXPECT_EQ(stages[i].stepdown, 1.0);
    EXPECT_EQ(stages[i].thickness, 1.5);
    EXPECT_EQ(stages[i].top_radius, 64.0);
    EXPECT_EQ(stages[i].tool_radius, 5.0);
  }
  // 90 deg: the centre stays at r_top - R = 59 mm, z = t/2 - k dz; ramps purely circumferential.
  const ConePath wall = annotated_cone_path(stages[4]);
  for_each(wall, ConeMove::contour, [&](std::size_t, const Eigen::Vector3d&,
                                        const Eigen::Vector3d& x, const ConeSegment& s) {
    EXPECT_NEAR(radius(x), 59.0, 1e-9);
    EXPECT_NEAR(x.z(), 0.75 - s.contour, 1e-12);
  });
  EXPECT_NEAR(cone_ramp_sweep(stages[4], 1), (1.0 / std::tan(rad(10.0))) / 59.0, 1e-12);

  const double safe_z = 20.0;
  for (const double pie : {360.0, 45.0}) {
    const auto st = vwall_stages(pie);
    const ConePath p = annotated_multistage_cone_path(st, safe_z);
    const auto& w = p.path.waypoints();
    int contours = 0, stage = 1, at_safe = 0;
    for (std::size_t i = 1; i < w.size(); ++i) {
      const ConeSegment& s = p.segments[i];
      EXPECT_GE(s.stage, stage);  // stages in order
      stage = s.stage;
      if (s.move == ConeMove::stage_change && w[i].position.z() == safe_z) ++at_safe;
      if (s.move == ConeMove::contour && p.segments[i - 1].move != ConeMove::contour) {
        ++contours;
        if (s.contour == 1 && pie == 360.0) {  // each stage starts at its stepdown angle
          EXPECT_NEAR(dtheta(unit(rad(stepdowns[s.stage - 1])), w[i - 1].position), 0.0, 1e-12);
        }
      }
      if (s.move == ConeMove::contour) {
        const ConePathOptions& o = st[s.stage - 1];
        EXPECT_NEAR(cad_distance(o, radius(w[i].position), w[i].position.z()).normal, 5.0, 1e-9);
      }
    }
    EXPECT_EQ(stage, 5);
    EXPECT_EQ(contours, 150);
    EXPECT_EQ(at_safe, 8);  // up to and across at safe_z between each pair of stages
    EXPECT_EQ(multistage_cone_path(st, safe_z).length(), p.path.length());
  }
}

TEST(ConePath, InvalidOptionsNameTheOption) {
  const ConePathOptions good = cone50(360.0);
  EXPECT_NO_THROW(cone_path(good));
  ConePathOptions o = good;
  o.wall_angle_deg = 95;
  EXPECT_EQ(message_of(o), "cone path: wall_angle_deg = 95 must lie in (0, 90]");
  const auto expect = [&](auto change, const std::string& name) {
    ConePathOptions x = good;
    change(x);
    const std::string m = message_of(x);
    EXPECT_NE(m.find("cone path: " + name), std::string::npos) << m;
  };
  expect([](auto& x) { x.wall_angle_deg = 0; }, "wall_angle_deg = 0");
  expect([](auto& x) { x.wall_angle_deg = std::nan(""); }, "wall_angle_deg");
  expect([](auto& x) { x.stepdown = -1; }, "stepdown = -1 must be > 0");
  expect([](auto& x) { x.contours = 0; }, "contours = 0 must be >= 1");
  expect([](auto& x) { x.top_radius = 0; }, "top_radius");
  expect([](auto& x) { x.thickness = -1.5; }, "thickness");
  expect([](auto& x) { x.tool_radius = std::numeric_limits<double>::infinity(); }, "tool_radius");
  expect([](auto& x) { x.pie_angle_deg = 400; }, "pie_angle_deg = 400 must lie in (0, 360]");
  expect([](auto& x) { x.pie_angle_deg = 0; }, "pie_angle_deg");
  expect([](auto& x) { x.ramp_angle_deg = 50; },
         "ramp_angle_deg = 50 must lie in (0, wall_angle_deg = 50)");
  expect([](auto& x) { x.ramp_angle_deg = 0.01; }, "ramp_angle_deg = 0.01 makes the ramp");
  expect([](auto& x) { x.stepdown_angle_deg = std::nan(""); }, "stepdown_angle_deg");
  expect([](auto& x) { x.feed = 0; }, "feed = 0");
  expect([](auto& x) { x.pie_angle_deg = 90, x.lift = 0; }, "lift = 0");
  expect([](auto& x) { x.chord_tolerance = 0; }, "chord_tolerance = 0");
  expect([](auto& x) { x.chord_tolerance = 1e-13; }, "chord_tolerance");
  expect([](auto& x) { x.approach_clearance = -1; }, "approach_clearance = -1");
  expect([](auto& x) { x.contours = 200; }, "contours = 200 with stepdown = 1 reach the axis");
  // Defaults of the required fields are rejected.
  EXPECT_NE(message_of(ConePathOptions{}).find("wall_angle_deg = 0"), std::string::npos);
  // Pies ignore the ramp angle; discs the lift.
  ConePathOptions pie = cone70(60, 45.0);
  pie.ramp_angle_deg = 80;
  EXPECT_NO_THROW(cone_path(pie));
  ConePathOptions disc = good;
  disc.lift = 0;
  EXPECT_NO_THROW(cone_path(disc));
  EXPECT_THROW(cone_contour_centre_radius(good, 31), std::invalid_argument);
  EXPECT_THROW(cone_ramp_sweep(good, 30), std::invalid_argument);
  EXPECT_THROW(cone_ramp_sweep(pie, 1), std::invalid_argument);

  auto stages = vwall_stages(45.0);
  EXPECT_THROW(multistage_cone_path({}, 20.0), std::invalid_argument);
  try {
    multistage_cone_path(stages, 5.0);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("safe_z = 5 must be >= 6.75"), std::string::npos)
        << e.what();
  }
  stages[2].stepdown = 0;
  try {
    multistage_cone_path(stages, 20.0);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "multistage cone path: stage 3: cone path: stepdown = 0 must be > 0");
  }
}
