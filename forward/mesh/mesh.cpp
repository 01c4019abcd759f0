#include "forward/mesh/mesh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <sstream>
#include <unordered_map>

namespace spifit::mesh {

const std::array<int, 4>& hex_face_corners(int face) {
  static const std::array<std::array<int, 4>, 6> corners = {{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
  return corners.at(static_cast<std::size_t>(face));
}

std::vector<int> Mesh::cell_nodes(int e) const {
  if (cell_type(e) == CellType::quad4) return {quads[e].begin(), quads[e].end()};
  const Hex& h = hex(e);
  return {h.begin(), h.end()};
}

Eigen::Vector3d Mesh::centroid(int e) const {
  if (cell_type(e) == CellType::quad4) {
    const auto& q = quads[e];
    return 0.25 * (nodes[q[0]] + nodes[q[1]] + nodes[q[2]] + nodes[q[3]]);
  }
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int v : hex(e)) c += nodes[v];
  return c / 8.0;
}

double Mesh::signed_area(int e) const {
  const auto& q = quads[e];
  const Eigen::Vector3d a = nodes[q[0]], b = nodes[q[1]], c = nodes[q[2]], d = nodes[q[3]];
  const Eigen::Vector3d n = (b - a).cross(c - a) + (c - a).cross(d - a);  // 2 x vector area
  const double area = 0.5 * n.norm();
  return n.z() >= 0.0 ? area : -area;
}

std::vector<int> select_nodes(const Mesh& m, const std::function<bool(const Eigen::Vector3d&)>& inside) {
  std::vector<int> out;
  for (int i = 0; i < m.num_nodes(); ++i) {
    if (inside(m.nodes[i])) out.push_back(i);
  }
  return out;
}

std::vector<int> select_elements(const Mesh& m, const std::function<bool(const Eigen::Vector3d&)>& inside) {
  std::vector<int> out;
  for (int e = 0; e < m.num_elements(); ++e) {
    if (inside(m.centroid(e))) out.push_back(e);
  }
  return out;
}

void merge_coincident_nodes(Mesh& m, double tol) {
  // Hash on a grid of cell size tol; compare with the 27 neighbouring cells.
  struct Key {
    long x, y, z;
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return std::hash<long>()(k.x * 73856093L ^ k.y * 19349663L ^ k.z * 83492791L);
    }
  };
  auto key = [&](const Eigen::Vector3d& p) {
    return Key{static_cast<long>(std::floor(p.x() / tol)), static_cast<long>(std::floor(p.y() / tol)),
               static_cast<long>(std::floor(p.z() / tol))};
  };
  std::unordered_map<Key, std::vector<int>, Hash> cells;
  std::vector<int> map(m.nodes.size(), -1);
  std::vector<Eigen::Vector3d> kept;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const Key k = key(m.nodes[i]);
    int found = -1;
    for (long dx = -1; dx <= 1 && found < 0; ++dx) {
      for (long dy = -1; dy <= 1 && found < 0; ++dy) {
        for (long dz = -1; dz <= 1 && found < 0; ++dz) {
          const auto it = cells.find(Key{k.x + dx, k.y + dy, k.z + dz});
          if (it == cells.end()) continue;
          for (int j : it->second) {
            if ((kept[j] - m.nodes[i]).norm() <= tol) {
              found = j;
              break;
            }
          }
        }
      }
    }
    if (found < 0) {
      found = static_cast<int>(kept.size());
      kept.push_back(m.nodes[i]);
      cells[k].push_back(found);
    }
    map[i] = found;
  }
  m.nodes = kept;
  for (auto& q : m.quads) {
    for (int& v : q) v = map[v];
  }
  for (auto& h : m.hexes) {
    for (int& v : h) v = map[v];
  }
  for (auto& [name, set] : m.node_sets) {
    for (int& v : set) v = map[v];
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  }
  // A constrained node keeps its constraint under its new number; merged with another node it
  // would be constrained and free (or constrained twice) at once.
  std::vector<int> merged_into(kept.size(), 0);
  for (int v : map) ++merged_into[static_cast<std::size_t>(v)];
  for (ConstrainedNode& c : m.constrained_nodes) {
    if (merged_into[static_cast<std::size_t>(map[c.node])] != 1)
      throw std::invalid_argument("merge_coincident_nodes: constrained node " + std::to_string(c.node) + " coincides with another node");
    c.node = map[c.node];
    for (auto& [master, w] : c.masters) master = map[master];
  }
  std::sort(m.constrained_nodes.begin(), m.constrained_nodes.end(), [](const auto& a, const auto& b) { return a.node < b.node; });
}

namespace {
std::string check_constrained_nodes(const Mesh& m) {
  std::ostringstream os;
  std::vector<char> constrained(m.nodes.size(), 0);
  for (const ConstrainedNode& c : m.constrained_nodes) {
    if (c.node < 0 || c.node >= m.num_nodes() || constrained[static_cast<std::size_t>(c.node)]) {
      os << "constrained node " << c.node << ": out of range or listed twice";
      return os.str();
    }
    constrained[static_cast<std::size_t>(c.node)] = 1;
  }
  for (const ConstrainedNode& c : m.constrained_nodes) {
    double sum = 0.0;
    for (const auto& [n, w] : c.masters) {
      if (n < 0 || n >= m.num_nodes() || constrained[static_cast<std::size_t>(n)]) {
        os << "constrained node " << c.node << ": master " << n << " out of range or itself constrained";
        return os.str();
      }
      sum += w;
    }
    if (c.masters.empty() || std::abs(sum - 1.0) > 1e-12) {
      os << "constrained node " << c.node << ": master weights sum to " << sum << ", not 1";
      return os.str();
    }
  }
  return "";
}

// A hexahedron's corners with the three neighbours whose edges form a right-handed triple in a
// well-shaped cell (the unit cube in VTK order).
constexpr int kHexCornerEdges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};

std::string check_hexes(const Mesh& m, std::vector<char>* used) {
  std::ostringstream os;
  for (int e = static_cast<int>(m.quads.size()); e < m.num_elements(); ++e) {
    const Hex& h = m.hex(e);
    for (int v : h) {
      if (v < 0 || v >= m.num_nodes()) {
        os << "element " << e << ": node index " << v << " out of range";
        return os.str();
      }
      (*used)[static_cast<std::size_t>(v)] = 1;
    }
    if (std::set<int>(h.begin(), h.end()).size() != 8) {
      os << "element " << e << ": repeated node (degenerate hexahedron)";
      return os.str();
    }
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d& p = m.nodes[h[c]];
      Eigen::Matrix3d edges;
      for (int k = 0; k < 3; ++k) edges.col(k) = m.nodes[h[kHexCornerEdges[c][k]]] - p;
      if (!(edges.determinant() > 0.0)) {
        os << "element " << e << ": corner Jacobian " << edges.determinant() << " <= 0 at its corner " << c
           << " (inverted, collapsed or badly ordered hexahedron)";
        return os.str();
      }
    }
  }
  for (const auto& [name, faces] : m.face_sets)
    for (const CellFace& f : faces)
      if (f.element < static_cast<int>(m.quads.size()) || f.element >= m.num_elements() || f.face < 0 || f.face > 5) {
        os << "face set " << name << ": element " << f.element << " face " << f.face << " is not a hexahedron's face";
        return os.str();
      }
  return "";
}
}  // namespace

std::string check_mesh(const Mesh& m) {
  std::ostringstream os;
  std::vector<char> used(m.nodes.size(), 0);
  for (int e = 0; e < static_cast<int>(m.quads.size()); ++e) {
    const auto& q = m.quads[e];
    for (int v : q) {
      if (v < 0 || v >= m.num_nodes()) {
        os << "element " << e << ": node index " << v << " out of range";
        return os.str();
      }
      used[v] = 1;
    }
    if (std::set<int>(q.begin(), q.end()).size() != 4) {
      os << "element " << e << ": repeated node (degenerate quad)";
      return os.str();
    }
    if (!(m.signed_area(e) > 0.0)) {
      os << "element " << e << ": area " << m.signed_area(e) << " <= 0 (zero-area or clockwise)";
      return os.str();
    }
    // Convexity: every corner turns the same way about +z.
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector3d a = m.nodes[q[c]], b = m.nodes[q[(c + 1) % 4]], d = m.nodes[q[(c + 3) % 4]];
      if ((b - a).cross(d - a).z() <= 0.0) {
        os << "element " << e << ": not convex at its corner " << c;
        return os.str();
      }
    }
  }
  if (std::string hexes = check_hexes(m, &used); !hexes.empty()) return hexes;
  for (int i = 0; i < m.num_nodes(); ++i) {
    if (!used[i]) {
      os << "node " << i << " belongs to no element";
      return os.str();
    }
  }
  return check_constrained_nodes(m);
}

std::vector<double> graded_points(double a, double b, int n, double ratio) {
  std::vector<double> x(n + 1);
  if (n <= 0) return {a};
  const double q = n > 1 ? std::pow(ratio, 1.0 / (n - 1)) : 1.0;  // size of element i+1 / element i
  double total = 0.0, h = 1.0;
  std::vector<double> sizes(n);
  for (int i = 0; i < n; ++i) {
    sizes[i] = h;
    total += h;
    h *= q;
  }
  x[0] = a;
  double acc = 0.0;
  for (int i = 0; i < n; ++i) {
    acc += sizes[i];
    x[i + 1] = a + (b - a) * acc / total;
  }
  x[n] = b;
  return x;
}

}  // namespace spifit::mesh
