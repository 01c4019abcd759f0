// A disc or pie with a coarsened centre (DiscOptions::coarse_inside): half the elements around the
// centre, the hanging nodes in the middle of the coarse elements' outer edges, the mesh whole, and
// errors for options that cannot be met.
#include "forward/mesh/disc_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace spifit::mesh {
namespace {

// The fine cone70 pie's mesh (48 elements per 45 deg along the rim, 34 graded rings).
DiscOptions fine_cone_pie() {
  DiscOptions o;
  o.radius = 91.5;
  o.angle_deg = 45.0;
  o.elements_per_45deg = 48;
  o.radial_elements = 34;
  o.radial_grading = 0.3;
  return o;
}

double area(const Mesh& m) {
  double a = 0.0;
  for (int e = 0; e < m.num_elements(); ++e) a += m.signed_area(e);
  return a;
}

// Every hanging node: two masters of weight 1/2 at whose midpoint it lies, both corners of one
// element (the coarse one whose edge it halves) that does not use the hanging node itself.
void expect_hanging_nodes_halve_coarse_edges(const Mesh& m) {
  for (const ConstrainedNode& h : m.constrained_nodes) {
    ASSERT_EQ(h.masters.size(), 2u);
    const auto [a, wa] = h.masters[0];
    const auto [b, wb] = h.masters[1];
    EXPECT_EQ(wa, 0.5);
    EXPECT_EQ(wb, 0.5);
    const Eigen::Vector3d mid = 0.5 * (m.nodes[static_cast<std::size_t>(a)] + m.nodes[static_cast<std::size_t>(b)]);
    EXPECT_LT((m.nodes[static_cast<std::size_t>(h.node)] - mid).norm(), 1e-12);
    int coarse = 0, fine = 0;
    for (const Quad& q : m.quads) {
      const bool has_a = std::count(q.begin(), q.end(), a) > 0, has_b = std::count(q.begin(), q.end(), b) > 0;
      const bool has_h = std::count(q.begin(), q.end(), h.node) > 0;
      coarse += has_a && has_b && !has_h;
      fine += has_h;
    }
    EXPECT_EQ(coarse, 1) << "hanging node " << h.node;
    EXPECT_EQ(fine, 2) << "hanging node " << h.node;
  }
}

TEST(CoarsenedDisc, PieHasHalfTheElementsInsideWithHangingNodesOnTheCoarseEdges) {
  const Mesh regular = disc_mesh(fine_cone_pie());
  DiscOptions o = fine_cone_pie();
  o.coarse_inside = 70.0;
  const Mesh m = disc_mesh(o);
  EXPECT_EQ(check_mesh(m), "");
  EXPECT_TRUE(regular.constrained_nodes.empty());
  EXPECT_EQ(regular.num_elements(), 2208);  // 24 x 24 core + 48 x 34 ring
  // 24 hanging nodes (every other node of a layer of 48 elements). Inside, a 12 x 12 core and
  // rings of 24 elements: 2208 - (576 - 144) - 24 f for f coarse rings.
  ASSERT_EQ(m.constrained_nodes.size(), 24u);
  const int f = (2208 - 432 - m.num_elements()) / 24;
  EXPECT_EQ(m.num_elements(), 2208 - 432 - 24 * f);
  EXPECT_GE(f, 1);
  expect_hanging_nodes_halve_coarse_edges(m);
  // The hanging layer is the first at or beyond 70 mm: its nodes lie between 70 mm and the next
  // ring (the layers bulge out to the bisector by 1.9 mm) and none on the pie's edges or rim.
  for (const ConstrainedNode& h : m.constrained_nodes) {
    const double r = m.nodes[static_cast<std::size_t>(h.node)].head<2>().norm();
    EXPECT_GT(r, 70.0 - 1e-9);
    EXPECT_LT(r, 74.0);
    for (const char* set : {"edge_theta0", "edge_theta1", "rim"}) {
      const auto& s = m.node_sets.at(set);
      EXPECT_FALSE(std::binary_search(s.begin(), s.end(), h.node)) << set;
    }
  }
  // Only the chords of the hanging layer move (to the coarse edges' midpoints): the area changes
  // by less than 1e-4 relative.
  EXPECT_NEAR(area(m) / area(regular), 1.0, 1e-4);
  // Nothing changes beyond the hanging layer: the rim nodes are the regular mesh's.
  EXPECT_EQ(m.node_sets.at("rim").size(), regular.node_sets.at("rim").size());
}

TEST(CoarsenedDisc, FullDiscHasHangingNodesInEverySubSector) {
  DiscOptions o;
  o.radius = 50.0;
  o.angle_deg = 360.0;
  o.elements_per_45deg = 8;  // 90 deg sub-sectors: 8 elements per kite side, 4 inside
  DiscOptions c = o;
  c.coarse_inside = 40.0;
  const Mesh regular = disc_mesh(o), m = disc_mesh(c);
  EXPECT_EQ(check_mesh(m), "");
  EXPECT_EQ(m.constrained_nodes.size(), 4u * 8u);
  expect_hanging_nodes_halve_coarse_edges(m);
  EXPECT_NEAR(area(m) / area(regular), 1.0, 1e-3);
  EXPECT_LT(m.num_elements(), regular.num_elements());
}

TEST(CoarsenedDisc, OptionsThatCannotBeMetAreErrorsNamingTheOption) {
  auto error_of = [](const DiscOptions& o) {
    try {
      disc_mesh(o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  DiscOptions odd = fine_cone_pie();
  odd.elements_per_45deg = 46;  // 23 elements per kite side: cannot be halved
  odd.coarse_inside = 70.0;
  EXPECT_NE(error_of(odd).find("coarse_inside needs an even number"), std::string::npos) << error_of(odd);
  DiscOptions core = fine_cone_pie();
  core.coarse_inside = 30.0;  // inside the 43.1 mm core
  EXPECT_NE(error_of(core).find("coarse_inside must lie between the core"), std::string::npos) << error_of(core);
  DiscOptions rim = fine_cone_pie();
  rim.coarse_inside = 91.4;  // beyond the last ring layer inside the rim
  EXPECT_NE(error_of(rim).find("coarse_inside must lie between the core"), std::string::npos) << error_of(rim);
  DiscOptions negative = fine_cone_pie();
  negative.coarse_inside = -1.0;
  EXPECT_NE(error_of(negative).find("coarse_inside must lie in [0, radius)"), std::string::npos) << error_of(negative);
}

TEST(MergeCoincidentNodes, RenumbersConstrainedNodesAndRefusesToMergeOne) {
  Mesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0.5, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.quads = {{0, 1, 5, 4}, {2, 5, 4, 3}};
  m.constrained_nodes.push_back({3, {{0, 0.5}, {2, 0.5}}});
  merge_coincident_nodes(m, 1e-9);
  ASSERT_EQ(m.num_nodes(), 5);
  ASSERT_EQ(m.constrained_nodes.size(), 1u);
  EXPECT_EQ(m.constrained_nodes[0].node, 2);              // node 3 after node 2 merged into node 1
  EXPECT_EQ(m.constrained_nodes[0].masters[1].first, 1);  // master 2 is node 1 now
  Mesh twice = m;
  twice.nodes.push_back(twice.nodes[2]);  // a copy of the constrained node
  twice.quads.push_back({0, 1, 5, 4});
  EXPECT_THROW(merge_coincident_nodes(twice, 1e-9), std::invalid_argument);
}

}  // namespace
}  // namespace spifit::mesh
