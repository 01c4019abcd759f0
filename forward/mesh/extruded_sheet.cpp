#include "forward/mesh/extruded_sheet.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace spifit::mesh {

std::vector<Eigen::Vector3d> nodal_normals(const Mesh& m) {
  std::vector<Eigen::Vector3d> n(m.nodes.size(), Eigen::Vector3d::Zero());
  for (const Quad& q : m.quads) {
    const Eigen::Vector3d a = (m.nodes[q[2]] - m.nodes[q[0]]).cross(m.nodes[q[3]] - m.nodes[q[1]]);
    for (int i : q) n[static_cast<std::size_t>(i)] += a;
  }
  for (std::size_t i = 0; i < n.size(); ++i) {
    const double len = n[i].norm();
    if (!(len > 0.0))
      throw std::invalid_argument("node " + std::to_string(i) +
                                  ": the normals of its elements cancel (no element, degenerate elements or inconsistent orientation)");
    n[i] /= len;
  }
  return n;
}

Mesh extrude_sheet(const Mesh& mid, double thickness, int layers) {
  if (!mid.hexes.empty()) throw std::invalid_argument("extrude_sheet: the mid-surface mesh has hexahedra");
  if (!(thickness > 0.0)) throw std::invalid_argument("extrude_sheet: thickness must be > 0, got " + std::to_string(thickness));
  if (layers < 1) throw std::invalid_argument("extrude_sheet: layers must be >= 1, got " + std::to_string(layers));
  for (const char* name : {"bottom", "top"})
    if (mid.node_sets.count(name)) throw std::invalid_argument(std::string("extrude_sheet: the mid-surface already has a node set ") + name);
  for (int l = 1; l <= layers; ++l)
    if (mid.element_sets.count("layer_" + std::to_string(l)))
      throw std::invalid_argument("extrude_sheet: the mid-surface already has an element set layer_" + std::to_string(l));

  const std::vector<Eigen::Vector3d> normal = nodal_normals(mid);
  const int n = mid.num_nodes(), m = static_cast<int>(mid.quads.size());
  Mesh s;
  s.nodes.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(layers + 1));
  for (int k = 0; k <= layers; ++k) {
    const double offset = thickness * (-0.5 + static_cast<double>(k) / layers);
    for (int i = 0; i < n; ++i) s.nodes.push_back(mid.nodes[static_cast<std::size_t>(i)] + offset * normal[static_cast<std::size_t>(i)]);
  }
  s.hexes.reserve(static_cast<std::size_t>(m) * static_cast<std::size_t>(layers));
  for (int l = 0; l < layers; ++l)
    for (const Quad& q : mid.quads) {
      const int lo = l * n, hi = (l + 1) * n;
      s.hexes.push_back({lo + q[0], lo + q[1], lo + q[2], lo + q[3], hi + q[0], hi + q[1], hi + q[2], hi + q[3]});
    }

  for (const auto& [name, nodes] : mid.node_sets) {
    std::vector<int>& set = s.node_sets[name];
    for (int k = 0; k <= layers; ++k)
      for (int i : nodes) set.push_back(k * n + i);
  }
  for (const auto& [name, elements] : mid.element_sets) {
    std::vector<int>& set = s.element_sets[name];
    for (int l = 0; l < layers; ++l)
      for (int e : elements) set.push_back(l * m + e);
  }
  for (int i = 0; i < n; ++i) {
    s.node_sets["bottom"].push_back(i);
    s.node_sets["top"].push_back(layers * n + i);
  }
  for (int l = 0; l < layers; ++l) {
    std::vector<int>& set = s.element_sets["layer_" + std::to_string(l + 1)];
    for (int q = 0; q < m; ++q) set.push_back(l * m + q);
  }
  for (int q = 0; q < m; ++q) {
    s.face_sets["bottom"].push_back({q, 0});
    s.face_sets["top"].push_back({(layers - 1) * m + q, 1});
  }

  for (int k = 0; k <= layers; ++k)
    for (const ConstrainedNode& c : mid.constrained_nodes) {
      ConstrainedNode h{k * n + c.node, c.masters};
      for (auto& [master, w] : h.masters) master += k * n;
      s.constrained_nodes.push_back(std::move(h));
    }
  std::sort(s.constrained_nodes.begin(), s.constrained_nodes.end(), [](const auto& a, const auto& b) { return a.node < b.node; });
  return s;
}

}  // namespace spifit::mesh
