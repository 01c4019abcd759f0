#pragma once
// The quadrilateral faces of a face set of a solid mesh as a surface mesh over the same nodes
// (the solid sheet's top surface, which the tool touches): face k is the k-th entry of the set,
// its corners counter-clockwise seen from outside (mesh::hex_face_corners).
#include "forward/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace spifit::mesh {

struct FaceSurface {
  Mesh mesh;                  // the solid's nodes; one quadrilateral per face of the set
  std::vector<int> element;   // the solid element of each face
  std::vector<int> face;      // its local face (0-5)
};

// std::invalid_argument when the mesh has no such face set.
FaceSurface face_surface(const Mesh& solid, const std::string& face_set);

}  // namespace spifit::mesh
