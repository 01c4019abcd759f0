#include "forward/mesh/face_surface.hpp"

#include <stdexcept>

namespace spifit::mesh {

FaceSurface face_surface(const Mesh& solid, const std::string& face_set) {
  const auto it = solid.face_sets.find(face_set);
  if (it == solid.face_sets.end()) throw std::invalid_argument("the solid mesh has no face set '" + face_set + "'");
  FaceSurface s;
  s.mesh.nodes = solid.nodes;
  for (const CellFace& cf : it->second) {
    const Hex& h = solid.hex(cf.element);
    const auto corners = hex_face_corners(cf.face);
    s.mesh.quads.push_back({h[static_cast<std::size_t>(corners[0])], h[static_cast<std::size_t>(corners[1])], h[static_cast<std::size_t>(corners[2])],
                            h[static_cast<std::size_t>(corners[3])]});
    s.element.push_back(cf.element);
    s.face.push_back(cf.face);
  }
  return s;
}

}  // namespace spifit::mesh
