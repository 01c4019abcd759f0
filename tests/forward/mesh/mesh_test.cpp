// Mesh generators: counts, exact or convergent areas, orientation, O-grid centre, node sets,
// grading and density bands, quality figures.
#include "forward/mesh/disc_mesh.hpp"
#include "forward/mesh/mesh_quality.hpp"
#include "forward/mesh/square_sheet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace spifit::mesh;

TEST(SquareSheet, FullUniform) {
  const Mesh m = square_sheet({182.0, 182.0, 50, 50, false, 1.0, 1.0});
  EXPECT_EQ(check_mesh(m), "");
  EXPECT_EQ(m.num_nodes(), 51 * 51);
  EXPECT_EQ(m.num_elements(), 2500);
  const auto q = mesh_quality(m, 1.2);
  EXPECT_NEAR(q.total_area, 182.0 * 182.0, 1e-8);
  EXPECT_NEAR(q.min_edge, 3.64, 1e-12);  // the §7.3 regular mesh: 3.64 mm squares
  EXPECT_NEAR(q.max_aspect_ratio, 1.0, 1e-12);
  EXPECT_NEAR(q.min_angle_deg, 90.0, 1e-9);
  EXPECT_EQ(m.node_sets.at("boundary").size(), 200u);
  EXPECT_EQ(m.node_sets.at("centre").size(), 1u);
  EXPECT_NEAR(m.nodes[m.node_sets.at("centre")[0]].norm(), 0.0, 1e-12);
}

TEST(SquareSheet, HalfWithSymmetryPlane) {
  const Mesh m = square_sheet({182.0, 182.0, 40, 40, true, 1.0, 1.0});
  EXPECT_EQ(check_mesh(m), "");
  EXPECT_EQ(m.num_elements(), 40 * 20);
  EXPECT_NEAR(mesh_quality(m, 1.2).total_area, 182.0 * 91.0, 1e-8);
  for (int i : m.node_sets.at("symmetry_y0")) EXPECT_EQ(m.nodes[i].y(), 0.0);
  EXPECT_EQ(m.node_sets.count("edge_ymin"), 0u);
  for (const auto& p : m.nodes) EXPECT_GE(p.y(), 0.0);
  // The symmetry plane is not clamped: the boundary set excludes its interior nodes.
  for (int i : m.node_sets.at("boundary")) EXPECT_TRUE(m.nodes[i].y() > 0 || std::abs(std::abs(m.nodes[i].x()) - 91.0) < 1e-9);
}

TEST(SquareSheet, GradedTowardsTheCentre) {
  const Mesh m = square_sheet({100.0, 100.0, 20, 20, false, 4.0, 4.0});
  EXPECT_EQ(check_mesh(m), "");
  const auto q = mesh_quality(m, 1.0);
  EXPECT_NEAR(q.total_area, 1e4, 1e-8);
  EXPECT_NEAR(q.max_edge / q.min_edge, 4.0, 1e-9);  // edge element / centre element
  EXPECT_THROW(square_sheet({100.0, 100.0, 21, 20, false, 4.0, 1.0}), std::invalid_argument);
}

TEST(GradedPoints, RatioAndEnds) {
  const auto x = graded_points(0.0, 10.0, 5, 3.0);
  ASSERT_EQ(x.size(), 6u);
  EXPECT_EQ(x.front(), 0.0);
  EXPECT_EQ(x.back(), 10.0);
  EXPECT_NEAR((x[5] - x[4]) / (x[1] - x[0]), 3.0, 1e-12);
}

class DiscAngles : public ::testing::TestWithParam<double> {};

TEST_P(DiscAngles, ValidOGridConvergentArea) {
  const double angle = GetParam();
  DiscOptions o;
  o.radius = 91.5;
  o.angle_deg = angle;
  o.elements_per_45deg = 48;
  const Mesh m = disc_mesh(o);
  EXPECT_EQ(check_mesh(m), "");
  const auto q = mesh_quality(m, 1.2);
  const double exact = 0.5 * o.radius * o.radius * angle * std::numbers::pi / 180.0;
  // Polygonal rim: relative deficit about (d theta)^2 / 6 with d theta = 45 deg / 48.
  const double dth = std::numbers::pi / 4 / 48;
  EXPECT_NEAR(q.total_area / exact, 1.0 - dth * dth / 6, 2e-6);
  // No degenerate element at the axis: the smallest corner is the sub-sector angle there
  // (a pie of angle beta cannot do better), and elements stay near-square elsewhere.
  const double beta = angle / std::ceil(angle / 90.0 - 1e-9);
  EXPECT_GT(q.min_angle_deg, 0.95 * std::min(beta, 45.0));
  // Usual shell quality bound: aspect ratio below 3 (measured 2.41 at 45 deg, 2.59 at 90 and
  // 360 deg next to the kite's outer corner); the axis element of a narrow pie is a small kite
  // with sides in the ratio 1 / tan(beta/2) (3.73 for 30 deg), which no sector mesh avoids.
  EXPECT_LT(q.max_aspect_ratio, std::max(3.0, 1.001 / std::tan(0.5 * beta * std::numbers::pi / 180.0)));
  ASSERT_EQ(m.node_sets.at("axis").size(), 1u);
  EXPECT_LT(m.nodes[m.node_sets.at("axis")[0]].norm(), 1e-9);
  for (int i : m.node_sets.at("rim")) EXPECT_NEAR(m.nodes[i].head<2>().norm(), o.radius, 1e-9);
  const int sectors = static_cast<int>(std::ceil(angle / 90.0 - 1e-9));
  const int rim_elements = static_cast<int>(m.node_sets.at("rim").size()) - (angle < 360 ? 1 : 0);
  EXPECT_NEAR(rim_elements, 48 * angle / 45.0, sectors);  // rounded per sub-sector
  if (angle < 360) {
    for (int i : m.node_sets.at("edge_theta0")) EXPECT_NEAR(m.nodes[i].y(), 0.0, 1e-9);
    const double g = angle * std::numbers::pi / 180.0;
    for (int i : m.node_sets.at("edge_theta1")) EXPECT_NEAR(std::cos(g) * m.nodes[i].y() - std::sin(g) * m.nodes[i].x(), 0.0, 1e-9);
    // Both edges carry the same number of nodes (cyclic conditions pair them).
    EXPECT_EQ(m.node_sets.at("edge_theta0").size(), m.node_sets.at("edge_theta1").size());
  } else {
    EXPECT_EQ(m.node_sets.count("edge_theta0"), 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Angles, DiscAngles, ::testing::Values(45.0, 90.0, 30.0, 120.0, 360.0));

// A denser band (the thesis's cone meshes are denser between two radii) has more elements per
// mm there: element centroids in the band, per mm, rise by about the band factor.
TEST(Disc, DensityBand) {
  DiscOptions o;
  o.radius = 65.5;
  o.angle_deg = 45.0;
  o.elements_per_45deg = 24;
  o.radial_elements = 40;
  o.core_radius = 10.0;
  const Mesh plain = disc_mesh(o);
  o.band_inner = 45.0;
  o.band_outer = 55.0;
  o.band_factor = 3.0;
  const Mesh banded = disc_mesh(o);
  EXPECT_EQ(check_mesh(banded), "");
  auto count = [](const Mesh& m, double r0, double r1) {
    int n = 0;
    for (int e = 0; e < m.num_elements(); ++e) {
      const double r = m.centroid(e).head<2>().norm();
      n += (r >= r0 && r < r1) ? 1 : 0;
    }
    return n;
  };
  EXPECT_EQ(plain.num_elements(), banded.num_elements());
  // Same number of ring elements: density in the band rises by f L / (L + (f - 1) w) with the
  // ring length L (from the kite's sides to the rim, about 65.5 - 10) and band width w = 10.
  const double L = 55.5, expected = 3.0 * L / (L + 2.0 * 10.0);
  const double ratio = static_cast<double>(count(banded, 46, 54)) / count(plain, 46, 54);
  EXPECT_NEAR(ratio, expected, 0.15 * expected);
}

TEST(MeshQuality, ThicknessOverLengthWarning) {
  // The thesis's fine cone mesh: 0.688 mm radial elements, t = 1.2 mm -> t/l about 1.7.
  const Mesh m = square_sheet({0.688 * 4, 0.688 * 4, 4, 4, false, 1.0, 1.0});
  const auto q = mesh_quality(m, 1.2);
  EXPECT_NEAR(q.max_thickness_over_length, 1.2 / 0.688, 1e-9);
  EXPECT_NE(describe_mesh_quality(q).find("above 1"), std::string::npos);
}

TEST(Mesh, CheckFindsBadElements) {
  Mesh m = square_sheet({1.0, 1.0, 1, 1, false, 1.0, 1.0});
  EXPECT_EQ(check_mesh(m), "");
  std::swap(m.quads[0][1], m.quads[0][3]);  // clockwise
  EXPECT_NE(check_mesh(m).find("area"), std::string::npos);
  m = square_sheet({1.0, 1.0, 1, 1, false, 1.0, 1.0});
  m.quads[0][2] = m.quads[0][1];  // repeated node
  EXPECT_NE(check_mesh(m).find("degenerate"), std::string::npos);
}
