#include "forward/mesh/square_sheet.hpp"

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
}  // namespace

Mesh square_sheet(const SquareSheetOptions& o) {
  if (!(o.length_x > 0 && o.length_y > 0)) throw std::invalid_argument("sheet lengths must be > 0");
  if (o.nx < 1 || o.ny < 1) throw std::invalid_argument("element counts must be >= 1");
  if (!(o.grading_x > 0 && o.grading_y > 0)) throw std::invalid_argument("grading ratios must be > 0");
  if ((o.grading_x != 1.0 && o.nx % 2) || (o.grading_y != 1.0 && o.ny % 2) || (o.half && o.ny % 2))
    throw std::invalid_argument("graded or half sheets need even element counts");
  const auto xs = centred_points(o.length_x, o.nx, o.grading_x);
  auto ys = centred_points(o.length_y, o.ny, o.grading_y);
  if (o.half) ys.erase(ys.begin(), ys.begin() + o.ny / 2);  // keep y >= 0
  const int cols = static_cast<int>(xs.size()), rows = static_cast<int>(ys.size());
  Mesh m;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < cols; ++i) m.nodes.emplace_back(xs[i], ys[j], 0.0);
  }
  auto id = [&](int i, int j) { return j * cols + i; };
  for (int j = 0; j + 1 < rows; ++j) {
    for (int i = 0; i + 1 < cols; ++i) m.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  }
  std::vector<int> all(m.quads.size());
  for (std::size_t e = 0; e < all.size(); ++e) all[e] = static_cast<int>(e);
  m.element_sets["all"] = all;
  auto& sx0 = m.node_sets["edge_xmin"];
  auto& sx1 = m.node_sets["edge_xmax"];
  auto& sy1 = m.node_sets["edge_ymax"];
  auto& sy0 = m.node_sets[o.half ? "symmetry_y0" : "edge_ymin"];
  for (int j = 0; j < rows; ++j) {
    sx0.push_back(id(0, j));
    sx1.push_back(id(cols - 1, j));
  }
  for (int i = 0; i < cols; ++i) {
    sy0.push_back(id(i, 0));
    sy1.push_back(id(i, rows - 1));
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
  return m;
}

}  // namespace spifit::mesh
