#pragma once
// Circular discs and pies (sectors) of any angle in the x-y plane, the first edge along +x, for the
// cone scenes (thesis §4.1.2, §8.1.2, §9.1.2). The centre is an O-grid: each sub-sector of at most
// 90 deg has a quadrilateral "kite" core (origin, a point on each edge at the core radius, and one
// on the bisector making right angles at the edge points) meshed as an n x n structured block, and
// a structured ring from the kite's outer sides to the rim, so no element is degenerate at the
// axis. The ring's radial spacing is uniform, geometric (radial_grading), or denser in a band
// (band_factor times as many elements per mm between band_inner and band_outer; the band replaces
// the grading).
//
// Circular rings (the vwall meshes of thesis Table 8.1: regular between r = 33 and 64 mm, denser
// between 45 and 55 mm, one ring of elements between 64 and 65.5 mm): with ring_start > 0 the
// ring is split into a transition from the kite's sides to the circle r = ring_start
// (transition_elements layers) and a circular part from ring_start to the rim whose node
// layers are circles, spaced as above (grading or band) on their true radii; rim_ring_width > 0
// makes the last of them one ring of elements of that radial width at the rim.
//
// Coarsened centre (coarse_inside > 0): inside that radius the core has (n/2) x (n/2) elements
// and the ring layers n instead of 2 n per sub-sector; on the first ring layer at or beyond it
// (measured along the sub-sector's edge) every other node hangs in the middle of a coarse
// element's outer edge (Mesh::constrained_nodes, weights 1/2). For cones, whose tool never reaches
// the floor's centre.
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
  double max_sector_deg = 90.0;       // largest O-grid sub-sector (45 or 90); 45 keeps the core
                                      // density of a 90 or 360 deg mesh equal to that of a 45 deg pie
  double ring_start = 0.0;            // mm; > 0: circular layers from here to the rim
  int transition_elements = 0;        // layers from the kite to ring_start; 0: about square
  double rim_ring_width = 0.0;        // mm; > 0: the outermost ring has this radial width
  double coarse_inside = 0.0;         // mm; > 0: half the elements around the centre inside this
                                      // radius (hanging nodes on the first layer beyond it)
};

// Node sets: "axis" (the centre node), "rim" (r = radius), "edge_theta0" and "edge_theta1" (the
// pie edges; absent for a full disc); element set "all". Throws std::invalid_argument on
// meaningless options.
Mesh disc_mesh(const DiscOptions& options);

}  // namespace spifit::mesh
