#pragma once
// Circular discs and pies (sectors) of any angle in the x-y plane, the first edge along +x,
// for the cone scenes (SPEC §3.3). The centre is an O-grid: each sub-sector of at most 90 deg
// has a quadrilateral "kite" core (origin, a point on each edge at the core radius, and one on
// the bisector making right angles at the edge points) meshed as an n x n structured block, and a structured ring from the kite's
// outer sides to the rim, so no element is degenerate at the axis. The ring's radial spacing
// is uniform, geometric (radial_grading), or denser in a band (band_factor times as many
// elements per mm between band_inner and band_outer; the band replaces the grading).
#include "forward/mesh/mesh.hpp"

namespace spifit::mesh {

struct DiscOptions {
  double radius = 91.5;               // mm, rim of the mesh
  double angle_deg = 45.0;            // pie angle, (0, 360]
  int elements_per_45deg = 48;        // along the rim (rounded to an even number per sub-sector)
  double core_radius = 0.0;           // 0: chosen so that core and ring elements have similar size
  int radial_elements = 0;            // in the ring; 0: about square elements at the rim
  double radial_grading = 1.0;        // outer / inner ring element size (geometric)
  double band_inner = 0.0, band_outer = 0.0;  // mm; band_outer > band_inner activates the band
  double band_factor = 1.0;           // element density multiplier in the band
};

// Node sets: "axis" (the centre node), "rim" (r = radius), "edge_theta0" and "edge_theta1" (the
// pie edges; absent for a full disc); element set "all". Throws std::invalid_argument on
// meaningless options.
Mesh disc_mesh(const DiscOptions& options);

}  // namespace spifit::mesh
