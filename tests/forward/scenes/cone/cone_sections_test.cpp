// Shape sections of a cone (thesis §8.2.1, §9.2): top and bottom surfaces along the director, depth, wall
// angle, twist, radial elongation, the wall-thickness plateau against the sine law, and the
// ends of the stages of a multistage path. Synthetic sections with known answers.
#include "forward/scenes/cone/cone_observable_log.hpp"
#include "forward/scenes/cone/cone_sections.hpp"
#include "forward/scenes/cone/sine_law.hpp"
#include "forward/toolpath/cone_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace spifit::scene {
namespace {

constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180.0; }

TEST(SineLaw, ThesisNumbers) {
  // Eq. 9.1: 70 deg, t0 = 1.2 mm -> 0.41 mm; Fig. 9.34: radial Green strain 377 %.
  EXPECT_NEAR(sine_law_thickness(1.2, 70.0), 0.41042417, 1e-8);
  EXPECT_NEAR(sine_law_thickness(1.5, 50.0), 1.5 * std::cos(rad(50.0)), 1e-15);
  EXPECT_NEAR(sine_law_radial_green_strain(70.0), 3.7743161, 1e-7);
  EXPECT_EQ(std::round(100.0 * sine_law_radial_green_strain(70.0)), 377.0);
  EXPECT_NEAR(sine_law_radial_green_strain(45.0), 0.5, 1e-15);
}

TEST(ConeSections, WallAnglesFromNeighbours) {
  const auto a = section_wall_angles({0.0, 1.0, 2.0, 2.0, 2.0}, {0.0, 0.0, 1.0, 2.0, 3.0});
  ASSERT_EQ(a.size(), 5u);
  EXPECT_NEAR(a[0], 0.0, 1e-12);                                  // one-sided: (0,0)-(1,0)
  EXPECT_NEAR(a[1], std::atan2(1.0, 2.0) * 180.0 / kPi, 1e-12);  // chord (0,0)-(2,1)
  EXPECT_NEAR(a[2], std::atan2(2.0, 1.0) * 180.0 / kPi, 1e-12);  // chord (1,0)-(2,2)
  EXPECT_NEAR(a[3], 90.0, 1e-12);                                 // vertical wall
  EXPECT_NEAR(a[4], 90.0, 1e-12);
}

// A cone section at theta0 = 22.5 deg: flat bottom (r < 5), a 60 deg wall from r = 5 to 15
// (sine-law thickness), flat flange beyond; nodes every mm of initial radius; the current
// position of each node is its initial (r, z) shape point rotated about z by 0.01 r0 rad
// (twist). The wall and flange lie on straight lines, directors are the unit normals.
struct SyntheticCone {
  double theta0 = 22.5, t0 = 1.2, alpha = 60.0;
  std::vector<SectionNode> nodes;
  SyntheticCone() {
    const double ta = std::tan(rad(alpha));
    for (int i = 0; i <= 20; ++i) {
      const double r0 = i;
      double r = r0, z = 0.0, h = t0;
      Eigen::Vector2d n(0.0, 1.0);  // (r, z) components of the director
      if (r0 < 15.0) z = -(15.0 - r0) * ta;
      if (r0 < 5.0) z = -10.0 * ta;
      if (r0 > 5.0 && r0 < 15.0) {
        h = sine_law_thickness(t0, alpha);
        n = Eigen::Vector2d(-std::sin(rad(alpha)), std::cos(rad(alpha)));
      }
      const double th = rad(theta0) + 0.01 * r0;
      SectionNode s;
      s.reference = Eigen::Vector3d(r0 * std::cos(rad(theta0)), r0 * std::sin(rad(theta0)), 0.0);
      s.position = Eigen::Vector3d(r * std::cos(th), r * std::sin(th), z);
      s.director = Eigen::Vector3d(n(0) * std::cos(th), n(0) * std::sin(th), n(1));
      s.thickness = h;
      nodes.push_back(s);
    }
  }
};

TEST(ConeSections, TopBottomDepthWallAngleAndTwistOfASyntheticCone) {
  const SyntheticCone c;
  const auto p = radial_section(c.nodes, c.theta0, c.t0);
  ASSERT_EQ(p.size(), 21u);
  const double ta = std::tan(rad(c.alpha)), sa = std::sin(rad(c.alpha)), ca = std::cos(rad(c.alpha));
  // Node r0 = 10 lies on the wall: top = mid + h/2 (-sin a, cos a) in (r, z).
  const SectionPoint& w = p[10];
  const double h = 1.2 * ca;
  EXPECT_NEAR(w.r0, 10.0, 1e-12);
  EXPECT_NEAR(w.r, 10.0, 1e-12);
  EXPECT_NEAR(w.z, -5.0 * ta, 1e-12);
  EXPECT_NEAR(w.thickness, h, 1e-15);
  EXPECT_NEAR(w.r_top, 10.0 - 0.5 * h * sa, 1e-12);
  EXPECT_NEAR(w.z_top, -5.0 * ta + 0.5 * h * ca, 1e-12);
  EXPECT_NEAR(w.r_bottom, 10.0 + 0.5 * h * sa, 1e-12);
  EXPECT_NEAR(w.z_bottom, -5.0 * ta - 0.5 * h * ca, 1e-12);
  EXPECT_NEAR(w.depth, 0.6 - w.z_top, 1e-12);
  EXPECT_NEAR(w.wall_angle_deg, 60.0, 1e-9);
  // Twist: u_theta = r sin(0.01 r0), dtheta = 0.01 r0 rad.
  EXPECT_NEAR(w.u_theta, 10.0 * std::sin(0.1), 1e-12);
  EXPECT_NEAR(w.dtheta_deg, 0.1 * 180.0 / kPi, 1e-10);
  EXPECT_NEAR(w.theta_deg, c.theta0 + 0.1 * 180.0 / kPi, 1e-10);
  // Axis node: no angle change, depth of the flat bottom.
  EXPECT_EQ(p[0].dtheta_deg, 0.0);
  EXPECT_NEAR(p[0].depth, 0.6 + 10.0 * ta - 0.6, 1e-12);
  // Flange: depth 0, flat.
  EXPECT_NEAR(p[20].depth, 0.0, 1e-12);
  EXPECT_NEAR(p[20].wall_angle_deg, 0.0, 1e-12);

  const auto edges = radial_elongation(c.nodes);
  ASSERT_EQ(edges.size(), 20u);
  // A wall edge: the chord between two wall nodes (r 1 mm, z tan(a), twisted by 0.01 rad apart).
  const double r1 = 10.0, r2 = 11.0;
  const double len = std::sqrt(r1 * r1 + r2 * r2 - 2.0 * r1 * r2 * std::cos(0.01) + ta * ta);
  EXPECT_NEAR(edges[10].initial_length, 1.0, 1e-12);
  EXPECT_NEAR(edges[10].ratio, len, 1e-12);
  EXPECT_NEAR(edges[10].r0_inner, 10.0, 1e-12);

  const SectionSummary s = summarise_section(p, edges, 60.0, c.t0);
  EXPECT_EQ(s.plateau_nodes, 9);  // r0 = 6 .. 14 (5 and 15 sit on the kinks: atan(tan 60 / 2) = 41 deg)
  EXPECT_NEAR(s.plateau_thickness, sine_law_thickness(1.2, 60.0), 1e-15);
  EXPECT_NEAR(s.sine_law_thickness, 0.6, 1e-15);
  EXPECT_NEAR(s.min_thickness, 0.6, 1e-15);
  EXPECT_NEAR(s.min_thickness_r0, 6.0, 1e-12);  // the first of the thinnest
  EXPECT_NEAR(s.max_elongation, edges[14].ratio, 1e-15);  // the outermost wall edge is twisted most
  EXPECT_GT(s.max_elongation, 1.0 / std::cos(rad(60.0)));
  // Another wall angle: no plateau.
  const SectionSummary none = summarise_section(p, edges, 70.0, c.t0);
  EXPECT_EQ(none.plateau_nodes, 0);
  EXPECT_TRUE(std::isnan(none.plateau_thickness));
}

TEST(ConeSections, CsvColumns) {
  const SyntheticCone c;
  const std::string csv = section_csv(radial_section(c.nodes, c.theta0, c.t0));
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "r0 [mm],r [mm],theta [deg],z [mm],thickness [mm],r_top [mm],z_top [mm],r_bottom [mm],z_bottom [mm],depth [mm],"
            "wall_angle [deg],u_theta [mm],dtheta [deg]");
  const std::string e = elongation_csv(radial_elongation(c.nodes));
  EXPECT_EQ(e.substr(0, e.find('\n')), "r0_inner [mm],r0_outer [mm],initial_length [mm],length [mm],ratio");
}

TEST(ConeSections, StagesEndWithTheirRetract) {
  auto stages = toolpath::vwall_stages(90.0);
  stages.resize(2);
  for (auto& o : stages) o.contours = 2;
  const toolpath::ConePath p = toolpath::annotated_multistage_cone_path(stages, 20.0);
  const std::vector<double> ends = stage_end_distances(p);
  ASSERT_EQ(ends.size(), 2u);
  const std::vector<double> d = p.path.waypoint_distances();
  EXPECT_LT(ends[0], ends[1]);
  EXPECT_DOUBLE_EQ(ends[1], p.path.length());
  // The first stage ends where its retract ends; what follows belongs to the stage change.
  std::size_t i = 0;
  while (d[i] < ends[0]) ++i;
  EXPECT_EQ(p.segments[i].move, toolpath::ConeMove::retract);
  EXPECT_EQ(p.segments[i].stage, 1);
  EXPECT_EQ(p.segments[i + 1].move, toolpath::ConeMove::stage_change);
  // A single cone: its path's end.
  const toolpath::ConePath one = toolpath::annotated_cone_path(stages[0]);
  EXPECT_EQ(stage_end_distances(one), std::vector<double>{one.path.length()});
}

}  // namespace
}  // namespace spifit::scene
