#pragma once
// A solid sheet: the mid-surface quadrilateral mesh of a sheet (square_sheet.hpp, disc_mesh.hpp)
// extruded through the thickness into layers of hexahedra, as the thesis meshes its BWD3D
// bricks (§3.1.2). Node levels lie at offsets -t/2 + k t / layers along each node's normal (the
// normalised sum of its quadrilaterals' normals, the shell's reference director), so a flat
// sheet's bottom is at z = -t/2 and its top, the tool side, at z = +t/2.
#include "forward/mesh/mesh.hpp"

namespace spifit::mesh {

// Numbering: node i of the mid-surface at level k (0 bottom .. layers top) is node
// k * n + i (n mid-surface nodes); the hexahedron above quadrilateral q in layer l (0 bottom) is
// element l * m + q (m quadrilaterals), with its bottom face on level l.
// Sets: each node set of the mid-surface becomes the nodes of all levels above its nodes, each
// element set the hexahedra of all layers above its quadrilaterals; added are node sets "bottom"
// and "top", element sets "layer_1" .. "layer_<layers>" (from the bottom) and face sets
// "bottom" (face 0 of the bottom layer) and "top" (face 1 of the top layer). Each hanging node
// of the mid-surface hangs at every level from the masters of that level.
// Throws std::invalid_argument for a mesh with hexahedra, thickness <= 0, layers < 1, or a
// mid-surface set named like an added one.
Mesh extrude_sheet(const Mesh& mid_surface, double thickness, int layers);

// The mid-surface nodes' unit normals (normalised sum of the diagonal cross products of the
// quadrilaterals around each node, which weights them by area); std::invalid_argument where
// they cancel.
std::vector<Eigen::Vector3d> nodal_normals(const Mesh& quadrilaterals);

}  // namespace spifit::mesh
