// Shell benchmark meshes: counts, nodes on the exact surface, faceted areas against the exact
// surface areas, outward element normals, node sets, option checks.
#include "forward/mesh/benchmark_meshes.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

using namespace spifit::mesh;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

Eigen::Vector3d normal(const Mesh& m, int e) {  // (x1 - x0) x (x3 - x0)
  const auto& q = m.quads[e];
  return (m.nodes[q[1]] - m.nodes[q[0]]).cross(m.nodes[q[3]] - m.nodes[q[0]]);
}

double total_area(const Mesh& m) {  // two triangles about the diagonal 0-2
  double a = 0.0;
  for (const auto& q : m.quads) {
    const Eigen::Vector3d p0 = m.nodes[q[0]], p1 = m.nodes[q[1]], p2 = m.nodes[q[2]], p3 = m.nodes[q[3]];
    a += 0.5 * ((p1 - p0).cross(p2 - p0).norm() + (p2 - p0).cross(p3 - p0).norm());
  }
  return a;
}

void expect_sets_sorted_unique(const Mesh& m) {
  for (const auto* sets : {&m.node_sets, &m.element_sets}) {
    for (const auto& [name, s] : *sets) {
      EXPECT_TRUE(std::adjacent_find(s.begin(), s.end(), std::greater_equal<int>()) == s.end()) << name;
    }
  }
  ASSERT_EQ(m.element_sets.at("all").size(), m.quads.size());
  for (int e = 0; e < m.num_elements(); ++e) EXPECT_EQ(m.element_sets.at("all")[e], e);
}
}  // namespace

TEST(BenchmarkMeshes, CylinderRoofQuarter) {
  const double R = 25.0, L = 25.0;
  const Mesh m = cylinder_roof_quarter(R, L, 40.0, 8);
  EXPECT_EQ(check_mesh(m), "");
  EXPECT_EQ(m.num_nodes(), 81);
  EXPECT_EQ(m.num_elements(), 64);
  expect_sets_sorted_unique(m);
  for (const auto& p : m.nodes) {
    EXPECT_NEAR(std::hypot(p.y(), p.z()), R, 1e-12);
    EXPECT_GE(p.x(), 0.0);
    EXPECT_LE(p.x(), L);
  }
  for (int e = 0; e < m.num_elements(); ++e) {
    Eigen::Vector3d radial = m.centroid(e);
    radial.x() = 0.0;
    EXPECT_GT(normal(m, e).dot(radial), 0.0) << "element " << e;
  }
  // Exact area R * angle * L; the 5 deg chords lose about (5 deg)^2 / 24 = 3e-4.
  const double exact = R * 40.0 * kDeg * L;
  EXPECT_NEAR(total_area(m), exact, 0.005 * exact);
  EXPECT_LT(total_area(m), exact);
  ASSERT_EQ(m.node_sets.at("point_A").size(), 1u);
  const Eigen::Vector3d a = m.nodes[m.node_sets.at("point_A")[0]];
  EXPECT_NEAR(a.x(), 0.0, 1e-12);
  EXPECT_NEAR(a.y(), R * std::sin(40.0 * kDeg), 1e-12);
  EXPECT_NEAR(a.z(), R * std::cos(40.0 * kDeg), 1e-12);
  for (const char* s : {"symmetry_x0", "diaphragm", "symmetry_crown", "free_edge"}) EXPECT_EQ(m.node_sets.at(s).size(), 9u) << s;
  for (int i : m.node_sets.at("symmetry_x0")) EXPECT_EQ(m.nodes[i].x(), 0.0);
  for (int i : m.node_sets.at("diaphragm")) EXPECT_NEAR(m.nodes[i].x(), L, 1e-12);
  for (int i : m.node_sets.at("symmetry_crown")) EXPECT_NEAR(m.nodes[i].z(), R, 1e-12);
  for (int i : m.node_sets.at("free_edge")) EXPECT_NEAR(std::atan2(m.nodes[i].y(), m.nodes[i].z()), 40.0 * kDeg, 1e-12);
}

TEST(BenchmarkMeshes, HemisphereQuarter) {
  const double R = 10.0;
  const Mesh m = hemisphere_quarter(R, 18.0, 8);
  EXPECT_EQ(check_mesh(m), "");
  EXPECT_EQ(m.num_nodes(), 81);
  EXPECT_EQ(m.num_elements(), 64);
  expect_sets_sorted_unique(m);
  for (const auto& p : m.nodes) {
    EXPECT_NEAR(p.norm(), R, 1e-12);
    EXPECT_GE(p.x(), 0.0);
    EXPECT_GE(p.y(), 0.0);
    EXPECT_GE(p.z(), 0.0);
  }
  for (int e = 0; e < m.num_elements(); ++e) EXPECT_GT(normal(m, e).dot(m.centroid(e)), 0.0) << "element " << e;
  const double exact = 2.0 * kPi * R * R * std::cos(18.0 * kDeg) / 4.0;
  EXPECT_NEAR(total_area(m), exact, 0.01 * exact);
  EXPECT_LT(total_area(m), exact);
  ASSERT_EQ(m.node_sets.at("load_x").size(), 1u);
  ASSERT_EQ(m.node_sets.at("load_y").size(), 1u);
  EXPECT_NEAR((m.nodes[m.node_sets.at("load_x")[0]] - Eigen::Vector3d(R, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((m.nodes[m.node_sets.at("load_y")[0]] - Eigen::Vector3d(0, R, 0)).norm(), 0.0, 1e-12);
  for (const char* s : {"symmetry_xz", "symmetry_yz", "equator", "hole"}) EXPECT_EQ(m.node_sets.at(s).size(), 9u) << s;
  for (int i : m.node_sets.at("symmetry_xz")) EXPECT_EQ(m.nodes[i].y(), 0.0);
  for (int i : m.node_sets.at("symmetry_yz")) EXPECT_EQ(m.nodes[i].x(), 0.0);
  for (int i : m.node_sets.at("equator")) EXPECT_EQ(m.nodes[i].z(), 0.0);
  for (int i : m.node_sets.at("hole")) EXPECT_NEAR(m.nodes[i].z(), R * std::cos(18.0 * kDeg), 1e-12);
}

TEST(BenchmarkMeshes, TwistedBeam) {
  const Mesh m = twisted_beam(12.0, 1.1, 90.0, 12, 2);
  EXPECT_EQ(m.num_nodes(), 39);
  EXPECT_EQ(m.num_elements(), 24);
  expect_sets_sorted_unique(m);
  EXPECT_EQ(m.node_sets.at("clamped").size(), 3u);
  EXPECT_EQ(m.node_sets.at("tip").size(), 3u);
  for (int i : m.node_sets.at("clamped")) {
    EXPECT_EQ(m.nodes[i].x(), 0.0);
    EXPECT_EQ(m.nodes[i].z(), 0.0);  // untwisted root: width along y
  }
  double zmin = 1e9, zmax = -1e9;
  for (int i : m.node_sets.at("tip")) {
    EXPECT_NEAR(m.nodes[i].x(), 12.0, 1e-12);
    EXPECT_NEAR(m.nodes[i].y(), 0.0, 1e-12);  // twisted 90 deg: the width runs along z
    zmin = std::min(zmin, m.nodes[i].z());
    zmax = std::max(zmax, m.nodes[i].z());
  }
  EXPECT_NEAR(zmin, -0.55, 1e-12);
  EXPECT_NEAR(zmax, 0.55, 1e-12);
  ASSERT_EQ(m.node_sets.at("tip_centre").size(), 1u);
  EXPECT_NEAR((m.nodes[m.node_sets.at("tip_centre")[0]] - Eigen::Vector3d(12, 0, 0)).norm(), 0.0, 1e-15);
  for (int e = 0; e < m.num_elements(); ++e) {  // normal turns with the twist: (0, -sin b, cos b)
    const double beta = 0.5 * kPi * m.centroid(e).x() / 12.0;
    EXPECT_GT(normal(m, e).normalized().dot(Eigen::Vector3d(0, -std::sin(beta), std::cos(beta))), 0.99) << e;
  }
  // Helicoid: each node at distance |s| from the x axis, |s| in {0, 0.55}.
  for (const auto& p : m.nodes) {
    const double r = std::hypot(p.y(), p.z());
    EXPECT_TRUE(r < 1e-12 || std::abs(r - 0.55) < 1e-12);
  }
}

TEST(BenchmarkMeshes, Strip) {
  const Mesh m = strip(10.0, 1.0, 10, 2);
  EXPECT_EQ(check_mesh(m), "");
  EXPECT_EQ(m.num_nodes(), 33);
  EXPECT_EQ(m.num_elements(), 20);
  expect_sets_sorted_unique(m);
  EXPECT_NEAR(total_area(m), 10.0, 1e-12);
  for (int e = 0; e < m.num_elements(); ++e) EXPECT_NEAR(normal(m, e).normalized().z(), 1.0, 1e-15);
  EXPECT_EQ(m.node_sets.at("clamped").size(), 3u);
  EXPECT_EQ(m.node_sets.at("tip").size(), 3u);
  EXPECT_EQ(m.node_sets.at("edge_ymin").size(), 11u);
  EXPECT_EQ(m.node_sets.at("edge_ymax").size(), 11u);
  for (int i : m.node_sets.at("clamped")) EXPECT_EQ(m.nodes[i].x(), 0.0);
  for (int i : m.node_sets.at("tip")) EXPECT_EQ(m.nodes[i].x(), 10.0);
  for (int i : m.node_sets.at("edge_ymin")) EXPECT_EQ(m.nodes[i].y(), -0.5);
  for (int i : m.node_sets.at("edge_ymax")) EXPECT_EQ(m.nodes[i].y(), 0.5);
  ASSERT_EQ(m.node_sets.at("tip_centre").size(), 1u);
  EXPECT_EQ(m.nodes[m.node_sets.at("tip_centre")[0]], Eigen::Vector3d(10, 0, 0));
  EXPECT_EQ(strip(10.0, 1.0, 10, 3).node_sets.count("tip_centre"), 0u);  // odd nw: no centre node
}

TEST(BenchmarkMeshes, InvalidOptionsThrow) {
  EXPECT_THROW(cylinder_roof_quarter(25, 25, 40, 0), std::invalid_argument);
  EXPECT_THROW(cylinder_roof_quarter(0, 25, 40, 4), std::invalid_argument);
  EXPECT_THROW(cylinder_roof_quarter(25, -1, 40, 4), std::invalid_argument);
  EXPECT_THROW(cylinder_roof_quarter(25, 25, 0, 4), std::invalid_argument);
  EXPECT_THROW(hemisphere_quarter(10, 18, 0), std::invalid_argument);
  EXPECT_THROW(hemisphere_quarter(-10, 18, 4), std::invalid_argument);
  EXPECT_THROW(hemisphere_quarter(10, 0, 4), std::invalid_argument);
  EXPECT_THROW(hemisphere_quarter(10, 90, 4), std::invalid_argument);
  EXPECT_THROW(hemisphere_quarter(10, std::nan(""), 4), std::invalid_argument);
  EXPECT_THROW(twisted_beam(12, 1.1, 90, 12, 3), std::invalid_argument);
  EXPECT_THROW(twisted_beam(12, 1.1, 90, 0, 2), std::invalid_argument);
  EXPECT_THROW(twisted_beam(0, 1.1, 90, 12, 2), std::invalid_argument);
  EXPECT_THROW(strip(10, 1, 0, 2), std::invalid_argument);
  EXPECT_THROW(strip(10, 0, 10, 2), std::invalid_argument);
  EXPECT_NO_THROW(strip(10, 1, 1, 1));
}
