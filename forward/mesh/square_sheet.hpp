#pragma once
// Structured square (rectangular) sheets centred on the origin in the x-y plane: full, or
// half with the symmetry plane y = 0 kept (line test, thesis §4.1.1), uniform or graded (elements
// smallest at the centre lines and growing geometrically towards the edges), and optionally
// coarsened where the tool never goes (docs/design/numerics-shell.md, "Coarsening away from the
// tool path").
#include "forward/mesh/mesh.hpp"

#include <Eigen/Core>

#include <functional>

namespace spifit::mesh {

struct SquareSheetOptions {
  double length_x = 182.0, length_y = 182.0;  // mm (full sheet)
  int nx = 50, ny = 50;                        // elements across the full sheet
  bool half = false;                           // keep y >= 0 only (ny/2 elements across it)
  double grading_x = 1.0, grading_y = 1.0;     // edge element size / centre element size
  // Coarsening: the cells of the nx x ny grid are merged into aligned blocks of 2^k x 2^k cells,
  // k up to coarse_levels, wherever keep_fine(lower corner, upper corner) is false for every cell
  // of the block (block_levels.hpp: neighbouring blocks differ by one level at most). A node in
  // the middle of a larger element's edge is a constrained node (Mesh::constrained_nodes).
  int coarse_levels = 0;
  std::function<bool(const Eigen::Vector2d&, const Eigen::Vector2d&)> keep_fine;
};

// Node sets: "edge_xmin", "edge_xmax", "edge_ymin" (full sheet), "edge_ymax", "symmetry_y0"
// (half sheet), "boundary" (the clamped edges: all edges but the symmetry plane), "centre"
// (the node nearest to the origin); element set "all". Nodes are numbered row by row from
// (xmin, ymin), elements by their lower-left corner in the same order. Throws std::invalid_argument on
// meaningless options (the scene readers report file and key first).
Mesh square_sheet(const SquareSheetOptions& options);

}  // namespace spifit::mesh
