#pragma once
// A shell mesh: nodes (mid-surface, mm) and 4-node quadrilaterals, numbered counter-clockwise
// seen from +z (the tool side), with named node and element sets. Generators: square_sheet.hpp,
// disc_mesh.hpp; quality: mesh_quality.hpp.
#include <Eigen/Core>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace spifit::mesh {

using Quad = std::array<int, 4>;

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
  std::map<std::string, std::vector<int>> node_sets;     // sorted, unique node indices
  std::map<std::string, std::vector<int>> element_sets;  // sorted, unique element indices
  std::vector<ConstrainedNode> constrained_nodes;         // sorted by node; empty for a conforming mesh

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_elements() const { return static_cast<int>(quads.size()); }
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

// Empty when the mesh is valid: node indices in range, four distinct nodes per quad, positive
// signed area (counter-clockwise), convex quads, no unused node; constrained nodes in range, each
// once, with masters that are not constrained and weights summing to 1; else the first problem.
std::string check_mesh(const Mesh& m);

// Node positions along [a, b] with n elements whose sizes vary geometrically by `ratio`
// (last element / first element); ratio 1 is uniform.
std::vector<double> graded_points(double a, double b, int n, double ratio);

}  // namespace spifit::mesh
