#include "forward/mesh/square_sheet.hpp"

#include "forward/mesh/block_levels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace spifit::mesh {

namespace {
// Coordinates across [-L/2, L/2] with n elements, refined towards 0 by `grading`.
std::vector<double> centred_points(double length, int n, double grading) {
  if (grading == 1.0) return graded_points(-0.5 * length, 0.5 * length, n, 1.0);
  // Symmetric: n/2 elements from the centre to each edge (n even), sizes growing by `grading`.
  const int h = n / 2;
  const auto right = graded_points(0.0, 0.5 * length, h, grading);
  std::vector<double> x;
  for (int i = h; i >= 1; --i) x.push_back(-right[i]);
  for (double v : right) x.push_back(v);
  return x;
}

// The grid of node lines, the cells' block levels and the nodes the blocks use.
struct SheetGrid {
  std::vector<double> xs, ys;
  int cols = 0, rows = 0;  // node lines
  BlockLevels blocks;      // per cell (row-major, (cols - 1) x (rows - 1))
  int id(int i, int j) const { return j * cols + i; }
  int cell(int i, int j) const { return j * (cols - 1) + i; }
  // Calls f(i0, j0, size) for every block, by lower-left corner row by row.
  template <typename F>
  void for_each_block(F f) const {
    for (int j = 0; j + 1 < rows; ++j)
      for (int i = 0; i + 1 < cols; ++i) {
        if (blocks.block_origin(cols - 1, i, j)) f(i, j, 1 << blocks.level[static_cast<std::size_t>(cell(i, j))]);
      }
  }
};

BlockLevels cell_levels(const SheetGrid& g, const SquareSheetOptions& o) {
  const int nx = g.cols - 1, ny = g.rows - 1;
  std::vector<int> limit(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 0);
  if (o.coarse_levels == 0) return balanced_block_levels(nx, ny, std::move(limit));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (!o.keep_fine(Eigen::Vector2d(g.xs[i], g.ys[j]), Eigen::Vector2d(g.xs[i + 1], g.ys[j + 1])))
        limit[static_cast<std::size_t>(g.cell(i, j))] = o.coarse_levels;
  return fewest_blocks(nx, ny, limit);
}

// A used grid node strictly inside a block's edge follows the edge's ends, interpolated by its
// position along the edge.
void add_hanging_nodes(const SheetGrid& g, const std::vector<int>& number, Mesh& m) {
  std::vector<char> seen(number.size(), 0);
  g.for_each_block([&](int i0, int j0, int s) {
    if (s == 1) return;
    // Edges as (start node, step in i, step in j).
    const int starts[4][2] = {{i0, j0}, {i0 + s, j0}, {i0, j0 + s}, {i0, j0}};
    const int steps[4][2] = {{1, 0}, {0, 1}, {1, 0}, {0, 1}};
    for (int e = 0; e < 4; ++e) {
      const int ia = starts[e][0], ja = starts[e][1], di = steps[e][0], dj = steps[e][1];
      const int ib = ia + s * di, jb = ja + s * dj;
      const double a = di ? g.xs[ia] : g.ys[ja], b = di ? g.xs[ib] : g.ys[jb];
      for (int k = 1; k < s; ++k) {
        const int n = g.id(ia + k * di, ja + k * dj);
        if (number[static_cast<std::size_t>(n)] < 0 || seen[static_cast<std::size_t>(n)]) continue;
        seen[static_cast<std::size_t>(n)] = 1;
        const double p = di ? g.xs[ia + k * di] : g.ys[ja + k * dj], t = (p - a) / (b - a);
        m.constrained_nodes.push_back({number[static_cast<std::size_t>(n)],
                                       {{number[static_cast<std::size_t>(g.id(ia, ja))], 1.0 - t},
                                        {number[static_cast<std::size_t>(g.id(ib, jb))], t}}});
      }
    }
  });
  std::sort(m.constrained_nodes.begin(), m.constrained_nodes.end(), [](const auto& x, const auto& y) { return x.node < y.node; });
}

// A master that is itself constrained (an edge end in the middle of a still larger element's
// edge) is replaced by its own masters, until only free nodes remain.
void resolve_chains(Mesh& m) {
  std::vector<int> where(m.nodes.size(), -1);
  for (std::size_t k = 0; k < m.constrained_nodes.size(); ++k) where[static_cast<std::size_t>(m.constrained_nodes[k].node)] = static_cast<int>(k);
  for (bool changed = true; changed;) {
    changed = false;
    for (ConstrainedNode& c : m.constrained_nodes) {
      std::vector<std::pair<int, double>> out;
      for (const auto& [n, w] : c.masters) {
        const int k = where[static_cast<std::size_t>(n)];
        if (k < 0) {
          out.emplace_back(n, w);
          continue;
        }
        for (const auto& [n2, w2] : m.constrained_nodes[static_cast<std::size_t>(k)].masters) out.emplace_back(n2, w * w2);
        changed = true;
      }
      std::sort(out.begin(), out.end());
      c.masters.clear();
      for (const auto& [n, w] : out) {
        if (!c.masters.empty() && c.masters.back().first == n) c.masters.back().second += w;
        else c.masters.emplace_back(n, w);
      }
    }
  }
}

void add_node_sets(const SheetGrid& g, const std::vector<int>& number, bool half, Mesh& m) {
  auto& sx0 = m.node_sets["edge_xmin"];
  auto& sx1 = m.node_sets["edge_xmax"];
  auto& sy1 = m.node_sets["edge_ymax"];
  auto& sy0 = m.node_sets[half ? "symmetry_y0" : "edge_ymin"];
  auto add = [&](std::vector<int>& set, int i, int j) {
    if (const int n = number[static_cast<std::size_t>(g.id(i, j))]; n >= 0) set.push_back(n);
  };
  for (int j = 0; j < g.rows; ++j) {
    add(sx0, 0, j);
    add(sx1, g.cols - 1, j);
  }
  for (int i = 0; i < g.cols; ++i) {
    add(sy0, i, 0);
    add(sy1, i, g.rows - 1);
  }
  std::vector<int> boundary;
  for (const char* s : {"edge_xmin", "edge_xmax", "edge_ymax", "edge_ymin"}) {
    if (m.node_sets.count(s)) boundary.insert(boundary.end(), m.node_sets[s].begin(), m.node_sets[s].end());
  }
  std::sort(boundary.begin(), boundary.end());
  boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());
  m.node_sets["boundary"] = boundary;
  for (auto& [name, set] : m.node_sets) std::sort(set.begin(), set.end());
  int centre = 0;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < m.num_nodes(); ++i) {
    if (m.nodes[i].norm() < best) { best = m.nodes[i].norm(); centre = i; }
  }
  m.node_sets["centre"] = {centre};
}

}  // namespace

Mesh square_sheet(const SquareSheetOptions& o) {
  if (!(o.length_x > 0 && o.length_y > 0)) throw std::invalid_argument("sheet lengths must be > 0");
  if (o.nx < 1 || o.ny < 1) throw std::invalid_argument("element counts must be >= 1");
  if (!(o.grading_x > 0 && o.grading_y > 0)) throw std::invalid_argument("grading ratios must be > 0");
  if ((o.grading_x != 1.0 && o.nx % 2) || (o.grading_y != 1.0 && o.ny % 2) || (o.half && o.ny % 2))
    throw std::invalid_argument("graded or half sheets need even element counts");
  if (o.coarse_levels < 0 || o.coarse_levels > 4) throw std::invalid_argument("coarsening levels must be 0 to 4");
  if (o.coarse_levels > 0 && !o.keep_fine) throw std::invalid_argument("coarsening needs the region to keep fine");
  SheetGrid g;
  g.xs = centred_points(o.length_x, o.nx, o.grading_x);
  g.ys = centred_points(o.length_y, o.ny, o.grading_y);
  if (o.half) g.ys.erase(g.ys.begin(), g.ys.begin() + o.ny / 2);  // keep y >= 0
  g.cols = static_cast<int>(g.xs.size());
  g.rows = static_cast<int>(g.ys.size());
  g.blocks = cell_levels(g, o);
  // The blocks' corners are the nodes, numbered row by row.
  std::vector<char> used(static_cast<std::size_t>(g.cols) * static_cast<std::size_t>(g.rows), 0);
  g.for_each_block([&](int i, int j, int s) {
    for (int n : {g.id(i, j), g.id(i + s, j), g.id(i + s, j + s), g.id(i, j + s)}) used[static_cast<std::size_t>(n)] = 1;
  });
  Mesh m;
  std::vector<int> number(used.size(), -1);
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.cols; ++i)
      if (used[static_cast<std::size_t>(g.id(i, j))]) {
        number[static_cast<std::size_t>(g.id(i, j))] = m.num_nodes();
        m.nodes.emplace_back(g.xs[i], g.ys[j], 0.0);
      }
  g.for_each_block([&](int i, int j, int s) {
    m.quads.push_back({number[static_cast<std::size_t>(g.id(i, j))], number[static_cast<std::size_t>(g.id(i + s, j))],
                       number[static_cast<std::size_t>(g.id(i + s, j + s))], number[static_cast<std::size_t>(g.id(i, j + s))]});
  });
  add_hanging_nodes(g, number, m);
  resolve_chains(m);
  std::vector<int> all(m.quads.size());
  for (std::size_t e = 0; e < all.size(); ++e) all[e] = static_cast<int>(e);
  m.element_sets["all"] = all;
  add_node_sets(g, number, o.half, m);
  return m;
}

}  // namespace spifit::mesh
