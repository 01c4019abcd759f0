#include "forward/mesh/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

namespace spifit::mesh {

MeshQuality mesh_quality(const Mesh& m, double thickness) {
  MeshQuality q;
  q.elements = m.num_elements();
  q.nodes = m.num_nodes();
  q.min_edge = std::numeric_limits<double>::infinity();
  q.min_angle_deg = 180.0;
  for (int e = 0; e < static_cast<int>(m.quads.size()); ++e) {
    const auto& quad = m.quads[e];
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector3d a = m.nodes[quad[c]], b = m.nodes[quad[(c + 1) % 4]], d = m.nodes[quad[(c + 3) % 4]];
      const double len = (b - a).norm();
      lo = std::min(lo, len);
      hi = std::max(hi, len);
      const double cosang = (b - a).normalized().dot((d - a).normalized());
      q.min_angle_deg = std::min(q.min_angle_deg, std::acos(std::clamp(cosang, -1.0, 1.0)) * 180.0 / std::numbers::pi);
    }
    q.min_edge = std::min(q.min_edge, lo);
    q.max_edge = std::max(q.max_edge, hi);
    q.max_aspect_ratio = std::max(q.max_aspect_ratio, hi / lo);
    q.max_thickness_over_length = std::max(q.max_thickness_over_length, thickness / lo);
    q.total_area += m.signed_area(e);
  }
  return q;
}

double median_edge_length(const Mesh& m) {
  std::vector<double> edges;
  edges.reserve(4 * m.quads.size());
  for (int e = 0; e < static_cast<int>(m.quads.size()); ++e)
    for (int c = 0; c < 4; ++c) edges.push_back((m.nodes[m.quads[e][(c + 1) % 4]] - m.nodes[m.quads[e][c]]).norm());
  if (edges.empty()) return 0.0;
  const auto mid = edges.begin() + static_cast<std::ptrdiff_t>(edges.size() / 2);
  std::nth_element(edges.begin(), mid, edges.end());
  return *mid;
}

std::string describe_mesh_quality(const MeshQuality& q) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%d elements, %d nodes, area %.6g mm^2; edges %.4g..%.4g mm; max aspect ratio %.3g; min angle %.1f deg; "
                "max t/l %.3g%s",
                q.elements, q.nodes, q.total_area, q.min_edge, q.max_edge, q.max_aspect_ratio, q.min_angle_deg,
                q.max_thickness_over_length,
                q.max_thickness_over_length > 3.0 ? " (above 3: too thick for the shell)"
                : q.max_thickness_over_length > 1.0 ? " (above 1: check the shell's accuracy)"
                                                     : "");
  return buf;
}

}  // namespace spifit::mesh
