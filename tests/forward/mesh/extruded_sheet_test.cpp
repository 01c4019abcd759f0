// Solid sheets: extrusion counts, numbering, volumes, sets and hanging nodes through the layers;
// the hexahedron checks of check_mesh; VTU cells of hexahedra.
#include "forward/mesh/extruded_sheet.hpp"
#include "forward/mesh/disc_mesh.hpp"
#include "forward/mesh/square_sheet.hpp"
#include "forward/mesh/vtu_writer.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace spifit::mesh;

namespace {
// Volume of a hexahedron from its six faces (divergence theorem with the bilinear faces split
// into two triangles about diagonal 0-2; exact for flat faces).
double hex_volume(const Mesh& m, int e) {
  const Hex& h = m.hex(e);
  double v = 0.0;
  for (int f = 0; f < 6; ++f) {
    const auto& c = hex_face_corners(f);
    const Eigen::Vector3d a = m.nodes[h[c[0]]], b = m.nodes[h[c[1]]], p = m.nodes[h[c[2]]], d = m.nodes[h[c[3]]];
    v += a.dot(b.cross(p)) / 6.0 + a.dot(p.cross(d)) / 6.0;
  }
  return v;
}
}  // namespace

TEST(ExtrudedSheet, CountsNumberingAndVolume) {
  const Mesh mid = square_sheet({20.0, 10.0, 4, 2, false, 1.0, 1.0, 0, {}});
  const Mesh s = extrude_sheet(mid, 1.2, 3);
  EXPECT_EQ(check_mesh(s), "");
  EXPECT_EQ(s.num_nodes(), 4 * mid.num_nodes());
  EXPECT_EQ(s.num_elements(), 3 * mid.num_elements());
  EXPECT_TRUE(s.quads.empty());
  EXPECT_EQ(s.cell_type(0), CellType::hex8);
  double volume = 0.0;
  for (int e = 0; e < s.num_elements(); ++e) volume += hex_volume(s, e);
  EXPECT_NEAR(volume, 20.0 * 10.0 * 1.2, 1e-10);
  // Node i of level k sits at k n + i, at z = -t/2 + k t / 3 above the mid-surface node.
  const int n = mid.num_nodes();
  for (int k = 0; k <= 3; ++k)
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d d = s.nodes[static_cast<std::size_t>(k * n + i)] - mid.nodes[static_cast<std::size_t>(i)];
      EXPECT_NEAR(d.z(), -0.6 + 0.4 * k, 1e-14);
      EXPECT_NEAR(d.head<2>().norm(), 0.0, 1e-14);
    }
  // The hexahedron above quadrilateral 5 in the middle layer.
  const Hex& h = s.hex(1 * mid.num_elements() + 5);
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(h[static_cast<std::size_t>(c)], n + mid.quads[5][static_cast<std::size_t>(c)]);
    EXPECT_EQ(h[static_cast<std::size_t>(c + 4)], 2 * n + mid.quads[5][static_cast<std::size_t>(c)]);
  }
  EXPECT_NEAR(s.centroid(1 * mid.num_elements() + 5).z(), 0.0, 1e-14);
}

TEST(ExtrudedSheet, SetsThroughTheLayers) {
  const Mesh mid = square_sheet({20.0, 10.0, 4, 2, true, 1.0, 1.0, 0, {}});
  const Mesh s = extrude_sheet(mid, 1.0, 2);
  const int n = mid.num_nodes(), m = mid.num_elements();
  EXPECT_EQ(s.node_sets.at("boundary").size(), 3 * mid.node_sets.at("boundary").size());
  EXPECT_EQ(s.node_sets.at("symmetry_y0").size(), 3 * mid.node_sets.at("symmetry_y0").size());
  for (int i : s.node_sets.at("symmetry_y0")) EXPECT_EQ(s.nodes[static_cast<std::size_t>(i)].y(), 0.0);
  EXPECT_EQ(s.element_sets.at("all").size(), static_cast<std::size_t>(2 * m));
  ASSERT_EQ(s.node_sets.at("top").size(), static_cast<std::size_t>(n));
  for (int i : s.node_sets.at("top")) EXPECT_NEAR(s.nodes[static_cast<std::size_t>(i)].z(), 0.5, 1e-14);
  for (int i : s.node_sets.at("bottom")) EXPECT_NEAR(s.nodes[static_cast<std::size_t>(i)].z(), -0.5, 1e-14);
  EXPECT_EQ(s.element_sets.at("layer_1").front(), 0);
  EXPECT_EQ(s.element_sets.at("layer_2").front(), m);
  // Face sets: the top faces' corners are top nodes, their outward normal +z; the bottom's -z.
  for (const char* side : {"top", "bottom"}) {
    const double sign = std::string(side) == "top" ? 1.0 : -1.0;
    ASSERT_EQ(s.face_sets.at(side).size(), static_cast<std::size_t>(m));
    for (const CellFace& f : s.face_sets.at(side)) {
      const auto& c = hex_face_corners(f.face);
      const Hex& h = s.hex(f.element);
      const Eigen::Vector3d a = s.nodes[h[c[0]]], b = s.nodes[h[c[1]]], p = s.nodes[h[c[2]]], d = s.nodes[h[c[3]]];
      EXPECT_GT(sign * (p - a).cross(d - b).z(), 0.0) << side;
      for (int k : c) EXPECT_NEAR(s.nodes[h[k]].z(), 0.5 * sign, 1e-14);
    }
  }
}

TEST(ExtrudedSheet, HangingNodesHangAtEveryLevel) {
  SquareSheetOptions o{64.0, 64.0, 16, 16, false, 1.0, 1.0, 1, {}};
  o.keep_fine = [](const Eigen::Vector2d& lo, const Eigen::Vector2d&) { return lo.x() < 0.0; };  // fine on the left half
  const Mesh mid = square_sheet(o);
  ASSERT_FALSE(mid.constrained_nodes.empty());
  const Mesh s = extrude_sheet(mid, 1.0, 2);
  EXPECT_EQ(check_mesh(s), "");
  ASSERT_EQ(s.constrained_nodes.size(), 3 * mid.constrained_nodes.size());
  const int n = mid.num_nodes();
  const ConstrainedNode& top = s.constrained_nodes.back();
  const ConstrainedNode& source = mid.constrained_nodes.back();
  EXPECT_EQ(top.node, 2 * n + source.node);
  for (std::size_t k = 0; k < top.masters.size(); ++k) {
    EXPECT_EQ(top.masters[k].first, 2 * n + source.masters[k].first);
    EXPECT_EQ(top.masters[k].second, source.masters[k].second);
  }
}

TEST(ExtrudedSheet, CurvedMidSurfaceKeepsThicknessAlongTheNormals) {
  // A disc bent into a shallow spherical cap: every node level lies on its normal.
  DiscOptions o;
  o.radius = 50.0;
  o.angle_deg = 90.0;
  o.elements_per_45deg = 6;
  Mesh mid = disc_mesh(o);
  for (auto& p : mid.nodes) p.z() = -0.002 * (p.x() * p.x() + p.y() * p.y());
  const auto normals = nodal_normals(mid);
  const Mesh s = extrude_sheet(mid, 2.0, 2);
  EXPECT_EQ(check_mesh(s), "");
  const int n = mid.num_nodes();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d d = s.nodes[static_cast<std::size_t>(2 * n + i)] - s.nodes[static_cast<std::size_t>(i)];
    EXPECT_NEAR(d.norm(), 2.0, 1e-12);
    EXPECT_NEAR(d.normalized().dot(normals[static_cast<std::size_t>(i)]), 1.0, 1e-12);
  }
}

TEST(ExtrudedSheet, BadInput) {
  const Mesh mid = square_sheet({2.0, 2.0, 2, 2, false, 1.0, 1.0, 0, {}});
  EXPECT_THROW(extrude_sheet(mid, 1.0, 0), std::invalid_argument);
  EXPECT_THROW(extrude_sheet(mid, 0.0, 1), std::invalid_argument);
  const Mesh solid = extrude_sheet(mid, 1.0, 1);
  EXPECT_THROW(extrude_sheet(solid, 1.0, 1), std::invalid_argument);
}

TEST(HexMeshCheck, NamesTheFirstProblem) {
  const Mesh mid = square_sheet({2.0, 2.0, 1, 1, false, 1.0, 1.0, 0, {}});
  Mesh s = extrude_sheet(mid, 1.0, 1);
  ASSERT_EQ(check_mesh(s), "");
  Mesh inverted = s;
  std::swap(inverted.hexes[0][1], inverted.hexes[0][3]);  // the bottom face turned clockwise
  EXPECT_NE(check_mesh(inverted).find("element 0: corner Jacobian"), std::string::npos) << check_mesh(inverted);
  Mesh repeated = s;
  repeated.hexes[0][7] = repeated.hexes[0][0];
  EXPECT_NE(check_mesh(repeated).find("repeated node"), std::string::npos);
  Mesh bad_face = s;
  bad_face.face_sets["top"].push_back({0, 6});
  EXPECT_NE(check_mesh(bad_face).find("face set top: element 0 face 6"), std::string::npos) << check_mesh(bad_face);
  Mesh squashed = s;
  squashed.nodes[static_cast<std::size_t>(s.hexes[0][6])].z() = -1.0;  // corner 6 pushed below the bottom
  EXPECT_NE(check_mesh(squashed).find("corner Jacobian"), std::string::npos);
}

TEST(Vtu, HexahedraCells) {
  const Mesh mid = square_sheet({2.0, 1.0, 2, 1, false, 1.0, 1.0, 0, {}});
  const Mesh s = extrude_sheet(mid, 1.0, 1);  // 12 nodes, 2 hexahedra
  VtuFrame f;
  f.cell_data = {{"layer", 1, {1.0, 1.0}}};
  const std::string v = vtu_text(s, f);
  EXPECT_NE(v.find("NumberOfPoints=\"12\" NumberOfCells=\"2\""), std::string::npos);
  EXPECT_NE(v.find(" 0 1 4 3 6 7 10 9 1 2 5 4 7 8 11 10\n"), std::string::npos);
  EXPECT_NE(v.find(" 8 16\n"), std::string::npos);
  EXPECT_NE(v.find(" 12 12\n"), std::string::npos);
}
