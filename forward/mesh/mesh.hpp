#pragma once
// A mesh of one sheet: nodes (mm) and cells of two types, 4-node quadrilaterals (a shell's
// mid-surface, numbered counter-clockwise seen from +z, the tool side) and 8-node hexahedra (a
// solid sheet), with named node, element and face sets. Elements are numbered quadrilaterals
// first, then hexahedra. Generators: square_sheet.hpp, disc_mesh.hpp (quadrilaterals),
// extruded_sheet.hpp (hexahedra through the thickness); quality: mesh_quality.hpp.
#include <Eigen/Core>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace spifit::mesh {

using Quad = std::array<int, 4>;
// VTK's hexahedron order: 0-3 the bottom face counter-clockwise seen from the top, 4-7 the top
// face, node 4 above node 0.
using Hex = std::array<int, 8>;

enum class CellType { quad4, hex8 };

// A hexahedron's face: element e (a hexahedron's element index) and its local face f, whose
// corners hex_face_corners(f) run counter-clockwise seen from outside: 0 bottom (0 3 2 1),
// 1 top (4 5 6 7), 2 (0 1 5 4), 3 (1 2 6 5), 4 (2 3 7 6), 5 (3 0 4 7).
struct CellFace {
  int element = -1;
  int face = -1;
  bool operator==(const CellFace& o) const { return element == o.element && face == o.face; }
};
const std::array<int, 4>& hex_face_corners(int face);

// A node whose motion follows other nodes: a hanging node of a coarsened sheet (square_sheet.hpp)
// lies on the edge of a larger element, and its six DOFs are the linear interpolation along that
// edge, sum w_k u_k over its masters (none of which is constrained; the weights sum to 1).
struct ConstrainedNode {
  int node = -1;
  std::vector<std::pair<int, double>> masters;
};

struct Mesh {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<Quad> quads;
  std::vector<Hex> hexes;                                 // element quads.size() + h is hexes[h]
  std::map<std::string, std::vector<int>> node_sets;     // sorted, unique node indices
  std::map<std::string, std::vector<int>> element_sets;  // sorted, unique element indices
  std::map<std::string, std::vector<CellFace>> face_sets;  // sorted by element, then face
  std::vector<ConstrainedNode> constrained_nodes;         // sorted by node; empty for a conforming mesh

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_elements() const { return static_cast<int>(quads.size() + hexes.size()); }
  CellType cell_type(int e) const { return e < static_cast<int>(quads.size()) ? CellType::quad4 : CellType::hex8; }
  // The hexahedron of element e (e >= quads.size()).
  const Hex& hex(int e) const { return hexes[static_cast<std::size_t>(e) - quads.size()]; }
  // The element's nodes in their cell order.
  std::vector<int> cell_nodes(int e) const;
  // Mean of the element's nodes.
  Eigen::Vector3d centroid(int e) const;
  // Area of the (possibly warped) quad: sum of the two triangles' areas about diagonal 0-2,
  // signed by the orientation about +z for flat meshes.
  double signed_area(int e) const;
};

std::vector<int> select_nodes(const Mesh& m, const std::function<bool(const Eigen::Vector3d&)>& inside);
std::vector<int> select_elements(const Mesh& m, const std::function<bool(const Eigen::Vector3d&)>& centroid_inside);

// Merges nodes closer than tol (spatial hashing; the first occurrence keeps its index order),
// renumbers the elements, the node sets and the constrained nodes. Deterministic. A constrained
// node that coincides with another node is an error (std::invalid_argument).
void merge_coincident_nodes(Mesh& m, double tol);

// Empty when the mesh is valid: node indices in range, distinct nodes in each cell, positive
// signed area (counter-clockwise) and convexity for quads, a positive corner Jacobian at each
// corner of a hexahedron, face sets naming hexahedra and faces 0-5, no unused node; constrained
// nodes in range, each once, with masters that are not constrained and weights summing to 1;
// else the first problem.
std::string check_mesh(const Mesh& m);

// Node positions along [a, b] with n elements whose sizes vary geometrically by `ratio`
// (last element / first element); ratio 1 is uniform.
std::vector<double> graded_points(double a, double b, int n, double ratio);

}  // namespace spifit::mesh
