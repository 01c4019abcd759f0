#pragma once
// Element quality of a shell mesh (its quadrilaterals; a solid sheet is judged on the mid-surface
// mesh it was extruded from): aspect ratio (longest / shortest edge), smallest interior angle,
// and thickness over the smallest in-plane length t/l (docs/design/numerics-shell.md, "Mesh and setting
// checks": warn above 1 — the thesis's fine cone mesh reaches 1.7 — refuse beyond about 3).
#include "forward/mesh/mesh.hpp"

#include <string>

namespace spifit::mesh {

struct MeshQuality {
  int elements = 0, nodes = 0;
  double min_edge = 0.0, max_edge = 0.0;
  double max_aspect_ratio = 0.0;
  double min_angle_deg = 0.0;
  double max_thickness_over_length = 0.0;  // t / shortest edge of an element
  double total_area = 0.0;
};

MeshQuality mesh_quality(const Mesh& m, double thickness);
// The median length of the elements' edges [mm] (0 for an empty mesh): the element size of a
// mostly uniform mesh, e.g. the period of the force ripple as the tool crosses elements.
double median_edge_length(const Mesh& m);
std::string describe_mesh_quality(const MeshQuality& q);

}  // namespace spifit::mesh
