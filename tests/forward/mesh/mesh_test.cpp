// Mesh generators: counts, exact or convergent areas, orientation, O-grid centre, node sets,
// grading and density bands, quality figures.
#include "forward/mesh/disc_mesh.hpp"
#include "forward/mesh/mesh_quality.hpp"
#include "forward/mesh/square_sheet.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

using namespace spifit::mesh;

TEST(SquareSheet, FullUniform) {
  const Mesh m = square_sheet({182.0, 182.0, 50, 50, false, 1.0, 1.0, 0, {}});
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
  const Mesh m = square_sheet({182.0, 182.0, 40, 40, true, 1.0, 1.0, 0, {}});
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
  const Mesh m = square_sheet({100.0, 100.0, 20, 20, false, 4.0, 4.0, 0, {}});
  EXPECT_EQ(check_mesh(m), "");
  const auto q = mesh_quality(m, 1.0);
  EXPECT_NEAR(q.total_area, 1e4, 1e-8);
  EXPECT_NEAR(q.max_edge / q.min_edge, 4.0, 1e-9);  // edge element / centre element
  EXPECT_THROW(square_sheet({100.0, 100.0, 21, 20, false, 4.0, 1.0, 0, {}}), std::invalid_argument);
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
  const Mesh m = square_sheet({0.688 * 4, 0.688 * 4, 4, 4, false, 1.0, 1.0, 0, {}});
  const auto q = mesh_quality(m, 1.2);
  EXPECT_NEAR(q.max_thickness_over_length, 1.2 / 0.688, 1e-9);
  EXPECT_NE(describe_mesh_quality(q).find("above 1"), std::string::npos);
}

TEST(Mesh, CheckFindsBadElements) {
  Mesh m = square_sheet({1.0, 1.0, 1, 1, false, 1.0, 1.0, 0, {}});
  EXPECT_EQ(check_mesh(m), "");
  std::swap(m.quads[0][1], m.quads[0][3]);  // clockwise
  EXPECT_NE(check_mesh(m).find("area"), std::string::npos);
  m = square_sheet({1.0, 1.0, 1, 1, false, 1.0, 1.0, 0, {}});
  m.quads[0][2] = m.quads[0][1];  // repeated node
  EXPECT_NE(check_mesh(m).find("degenerate"), std::string::npos);
}

// The vwall meshes of thesis Table 8.1 (§8.1): 48 elements per 45 deg beyond r = 33 mm, circular
// node layers regular between 33 and 64 mm and twice as dense between 45 and 55 mm, one ring of
// elements between 64 and 65.5 mm (the backing-plate hole, footnote 2 of §8.1).
DiscOptions vwall_like(double angle) {
  DiscOptions o;
  o.radius = 65.5;
  o.angle_deg = angle;
  o.elements_per_45deg = 48;
  o.max_sector_deg = 45.0;
  o.core_radius = 25.0;
  o.ring_start = 33.0;
  o.radial_elements = 27;
  o.band_inner = 45.0;
  o.band_outer = 55.0;
  o.band_factor = 2.0;
  o.rim_ring_width = 1.5;
  return o;
}

TEST(Disc, CircularRingsWithBandAndRimRing) {
  const Mesh m = disc_mesh(vwall_like(45.0));
  EXPECT_EQ(check_mesh(m), "");
  // Radii of the nodes on the pie edge theta = 0 beyond ring_start: the circular layers.
  std::vector<double> r;
  for (int i : m.node_sets.at("edge_theta0"))
    if (m.nodes[i].x() >= 33.0 - 1e-9) r.push_back(m.nodes[i].x());
  std::sort(r.begin(), r.end());
  ASSERT_EQ(r.size(), 27u + 2u);  // 27 spaced elements + the rim ring: 29 layers
  EXPECT_NEAR(r.front(), 33.0, 1e-9);
  EXPECT_NEAR(r[r.size() - 2], 64.0, 1e-9);
  EXPECT_NEAR(r.back(), 65.5, 1e-9);
  // Every node at a layer radius lies on that circle (layers are circles, not blends).
  for (const auto& p : m.nodes) {
    const double rho = p.head<2>().norm();
    if (rho < 33.0 - 1e-9) continue;
    const double nearest = *std::min_element(r.begin(), r.end(), [&](double a, double b) { return std::abs(a - rho) < std::abs(b - rho); });
    EXPECT_NEAR(rho, nearest, 1e-9);
  }
  // Spacing: uniform outside the band, half of it inside (band factor 2): 21 mm outside and
  // 10 mm x 2 inside over 27 elements gives 41/27 = 1.5185 mm and 0.7593 mm.
  const double h = 41.0 / 27.0;
  EXPECT_NEAR(r[1] - r[0], h, 1e-6);
  EXPECT_NEAR(r[26] - r[25], h, 1e-6);
  int in_band = 0;
  for (std::size_t i = 1; i + 1 < r.size(); ++i)
    if (r[i - 1] >= 45.0 + 1e-6 && r[i] <= 55.0 - 1e-6) {
      EXPECT_NEAR(r[i] - r[i - 1], 0.5 * h, 1e-3);
      ++in_band;
    }
  EXPECT_GE(in_band, 11);
  // 48 elements per 45 deg in the circumferential direction beyond r = 33 mm.
  const int rim_elements = static_cast<int>(m.node_sets.at("rim").size()) - 1;
  EXPECT_EQ(rim_elements, 48);
}

// With 45-degree sub-sectors a 90-degree pie and a full disc are 2 and 8 copies of the 45-degree
// pie (same element sizes everywhere), as the thesis's meshes nearly are (Table 8.1: 2320, 4506,
// 17376 elements; 2244, 4450, 17571 nodes).
TEST(Disc, FortyFiveDegreeSubSectorsScaleWithTheAngle) {
  const Mesh m45 = disc_mesh(vwall_like(45.0)), m90 = disc_mesh(vwall_like(90.0)), m360 = disc_mesh(vwall_like(360.0));
  for (const Mesh* m : {&m45, &m90, &m360}) EXPECT_EQ(check_mesh(*m), "");
  EXPECT_EQ(m90.num_elements(), 2 * m45.num_elements());
  EXPECT_EQ(m360.num_elements(), 8 * m45.num_elements());
  const int shared_edge = static_cast<int>(m45.node_sets.at("edge_theta0").size());
  EXPECT_EQ(static_cast<int>(m90.nodes.size()), 2 * static_cast<int>(m45.nodes.size()) - shared_edge);
  EXPECT_EQ(static_cast<int>(m360.nodes.size()), 8 * (static_cast<int>(m45.nodes.size()) - shared_edge) + 1);
  std::printf("vwall-like meshes: 45 deg %d elements %zu nodes; 90 deg %d / %zu; 360 deg %d / %zu\n", m45.num_elements(), m45.nodes.size(),
              m90.num_elements(), m90.nodes.size(), m360.num_elements(), m360.nodes.size());
  EXPECT_THROW(disc_mesh([] {
                 auto o = vwall_like(45.0);
                 o.ring_start = 20.0;  // inside the kite
                 return o;
               }()),
               std::invalid_argument);
}
