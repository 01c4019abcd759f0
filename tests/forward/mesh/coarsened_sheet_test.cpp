// Coarsening a sheet away from the tool path: the quadtree levels (2:1 balance), the distance of
// a cell to a path piece, and the coarsened mesh with its hanging nodes.
#include "forward/mesh/block_levels.hpp"
#include "forward/mesh/segment_distance.hpp"
#include "forward/mesh/square_sheet.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace spifit::mesh {
namespace {

// Cell limits of a grid: 0 (stay fine) on a few scattered cells, `top` elsewhere.
std::vector<int> scattered_limits(int nx, int ny, int top) {
  std::vector<int> limit(static_cast<std::size_t>(nx * ny), top);
  for (int k = 0; k < nx * ny; k += 97) limit[static_cast<std::size_t>(k)] = 0;
  return limit;
}

TEST(BlockLevels, NeighbouringBlocksDifferByOneLevelAtMostAndRespectEachCellsLimit) {
  const int nx = 37, ny = 23;
  const std::vector<int> limit = scattered_limits(nx, ny, 4);
  for (const BlockLevels& b : {balanced_block_levels(nx, ny, limit), balanced_block_levels(nx, ny, limit, 5, 3), fewest_blocks(nx, ny, limit)}) {
    auto at = [&](int i, int j) { return b.level[static_cast<std::size_t>(j * nx + i)]; };
    int origins = 0;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        EXPECT_LE(at(i, j), limit[static_cast<std::size_t>(j * nx + i)]);
        if (i + 1 < nx) {
          EXPECT_LE(std::abs(at(i, j) - at(i + 1, j)), 1) << i << "," << j;
        }
        if (j + 1 < ny) {
          EXPECT_LE(std::abs(at(i, j) - at(i, j + 1)), 1) << i << "," << j;
        }
        if (!b.block_origin(nx, i, j)) continue;
        ++origins;
        // The block is inside the grid and all of its cells carry its level.
        const int s = 1 << at(i, j);
        ASSERT_LE(i + s, nx);
        ASSERT_LE(j + s, ny);
        for (int jj = j; jj < j + s; ++jj)
          for (int ii = i; ii < i + s; ++ii) EXPECT_EQ(at(ii, jj), at(i, j));
      }
    EXPECT_EQ(origins, b.blocks);
    EXPECT_LT(b.blocks, nx * ny / 3);  // it did coarsen: 218 to 254 blocks for 851 cells
  }
}

TEST(BlockLevels, TheBestShiftPutsAnOddRowWhereTheCellsStayFine) {
  // 50 x 25 cells, fine along j = 0 (a half sheet's symmetry line, where the tool runs): without a
  // shift the odd 25th row lies at the clamped edge and holds fine cells there.
  const int nx = 50, ny = 25;
  std::vector<int> limit(static_cast<std::size_t>(nx * ny), 3);
  for (int i = 0; i < nx; ++i) limit[static_cast<std::size_t>(i)] = 0;
  const BlockLevels plain = balanced_block_levels(nx, ny, limit), best = fewest_blocks(nx, ny, limit);
  EXPECT_LT(best.blocks, plain.blocks);
  EXPECT_EQ(plain.level[static_cast<std::size_t>((ny - 1) * nx + nx / 2)], 0);
  EXPECT_GT(best.level[static_cast<std::size_t>((ny - 1) * nx + nx / 2)], 0);
}

TEST(SegmentDistance, RectangleToSegmentInTheClosedForms) {
  const Eigen::Vector2d lo(0.0, 0.0), hi(1.0, 1.0);
  EXPECT_DOUBLE_EQ(rectangle_segment_distance(lo, hi, {2.0, 2.0}, {3.0, 3.0}), std::sqrt(2.0));  // beyond a corner
  EXPECT_DOUBLE_EQ(rectangle_segment_distance(lo, hi, {-1.0, 3.0}, {2.0, 3.0}), 2.0);            // parallel above
  EXPECT_DOUBLE_EQ(rectangle_segment_distance(lo, hi, {-1.0, -1.0}, {2.0, 2.0}), 0.0);           // across
  EXPECT_DOUBLE_EQ(rectangle_segment_distance(lo, hi, {0.5, 0.5}, {0.5, 0.5}), 0.0);             // a point inside
  EXPECT_DOUBLE_EQ(rectangle_segment_distance(lo, hi, {3.0, -1.0}, {3.0, 4.0}), 2.0);            // a point of the segment nearest a side
  EXPECT_NEAR(rectangle_segment_distance(lo, hi, {3.0, 0.0}, {0.0, 3.0}), std::sqrt(0.5), 1e-15);  // a corner nearest the segment
}

SquareSheetOptions line_half_band(int levels, double band) {
  SquareSheetOptions o;
  o.length_x = o.length_y = 182.0;
  o.nx = o.ny = 50;
  o.half = true;
  o.coarse_levels = levels;
  o.keep_fine = [band](const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
    return rectangle_segment_distance(lo, hi, {-50.0, 0.0}, {50.0, 0.0}) <= band;
  };
  return o;
}

TEST(SquareSheet, CoarsenedAwayFromTheToolPathItIsAValidMeshWhoseHangingNodesLieOnLargerEdges) {
  for (int levels : {1, 2, 3}) {
    const Mesh m = square_sheet(line_half_band(levels, 20.0));
    EXPECT_EQ(check_mesh(m), "") << levels;
    EXPECT_LT(m.num_elements(), 1250);
    double area = 0.0;
    for (int e = 0; e < m.num_elements(); ++e) area += m.signed_area(e);
    EXPECT_NEAR(area, 182.0 * 91.0, 1e-9);
    // Fine within the band: every element whose centroid is within 20 mm of the path has the
    // regular size.
    for (int e = 0; e < m.num_elements(); ++e) {
      const Eigen::Vector3d c = m.centroid(e);
      if (std::abs(c.x()) < 50.0 && c.y() < 20.0) {
        EXPECT_NEAR(m.signed_area(e), 3.64 * 3.64, 1e-9) << e;
      }
    }
    ASSERT_FALSE(m.constrained_nodes.empty());
    const std::set<int> boundary(m.node_sets.at("boundary").begin(), m.node_sets.at("boundary").end());
    for (const ConstrainedNode& h : m.constrained_nodes) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (const auto& [n, w] : h.masters) p += w * m.nodes[static_cast<std::size_t>(n)];
      EXPECT_NEAR((p - m.nodes[static_cast<std::size_t>(h.node)]).norm(), 0.0, 1e-12) << h.node;
      EXPECT_FALSE(boundary.count(h.node)) << h.node;
      // Some element has it strictly inside an edge without using it: it hangs.
      bool hangs = false;
      for (const Quad& q : m.quads)
        for (int k = 0; k < 4 && !hangs; ++k) {
          const Eigen::Vector3d a = m.nodes[static_cast<std::size_t>(q[k])], b = m.nodes[static_cast<std::size_t>(q[(k + 1) % 4])];
          const Eigen::Vector3d x = m.nodes[static_cast<std::size_t>(h.node)];
          hangs = (x - a).cross(b - a).norm() < 1e-9 && (x - a).dot(x - b) < 0.0;
        }
      EXPECT_TRUE(hangs) << h.node;
    }
  }
}

TEST(SquareSheet, WithoutCoarseningTheNumberingIsRowByRow) {
  const Mesh m = square_sheet(line_half_band(0, 20.0));
  ASSERT_EQ(m.num_nodes(), 51 * 26);
  ASSERT_EQ(m.num_elements(), 50 * 25);
  EXPECT_TRUE(m.constrained_nodes.empty());
  EXPECT_NEAR(m.nodes[52].x(), -91.0 + 3.64, 1e-12);
  EXPECT_NEAR(m.nodes[52].y(), 3.64, 1e-12);
  EXPECT_EQ(m.quads[51], (Quad{52, 53, 104, 103}));
}

}  // namespace
}  // namespace spifit::mesh
