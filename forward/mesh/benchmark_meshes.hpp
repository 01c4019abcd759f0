#pragma once
// The classic shell benchmark meshes (MacNeal & Harder 1985; Belytschko et al. 1985), structured
// and merge-free: node index = i + (nu + 1) * j for grid point (i, j), quads counter-clockwise in
// (i, j), so the element normal (x1 - x0) x (x3 - x0) points away from the axis or centre of the
// curved surfaces and along +z for the flat strip. Every mesh has the element set "all"; all
// sets are sorted and unique. Each generator throws std::invalid_argument on meaningless options.
#include "forward/mesh/mesh.hpp"

namespace spifit::mesh {

// Scordelis-Lo roof, quarter model: cylinder of radius `radius` about the x axis, x in
// [0, length_half] (x = 0 the midspan symmetry plane, x = length_half the end diaphragm), arc
// from the crown theta = 0 to theta = angle_deg (40 for the standard 80 deg roof), point
// (x, R sin(theta), R cos(theta)); n elements along x and n along the arc. Node sets:
// "symmetry_x0", "diaphragm", "symmetry_crown" (theta = 0), "free_edge" (theta = angle_deg),
// "point_A" (free edge at midspan, the standard output point).
Mesh cylinder_roof_quarter(double radius, double length_half, double angle_deg, int n);

// Pinched hemisphere with an 18 deg polar hole, quarter model: sphere of radius `radius` about
// the origin, azimuth phi in [0, 90] deg (x, y >= 0), from the equator z = 0 up to the hole edge
// at colatitude hole_deg; n elements in azimuth and n in latitude. Node sets: "symmetry_xz"
// (y = 0), "symmetry_yz" (x = 0), "equator", "hole", "load_x" (node (R, 0, 0)), "load_y"
// (node (0, R, 0)).
Mesh hemisphere_quarter(double radius, double hole_deg, int n);

// MacNeal-Harder twisted beam: x in [0, length], s in [-width/2, width/2] twisted about the x
// axis by beta = twist_deg * x / length: point (x, s cos(beta), s sin(beta)); nl x nw elements
// (standard 12 x 2), nw even. Node sets: "clamped" (x = 0), "tip" (x = length), "tip_centre"
// (x = length, s = 0).
Mesh twisted_beam(double length, double width, double twist_deg, int nl, int nw);

// Flat strip [0, length] x [-width/2, width/2] in the x-y plane (cantilevers, the limit-moment
// strip); nl x nw elements. Node sets: "clamped" (x = 0), "tip" (x = length), "edge_ymin",
// "edge_ymax", and "tip_centre" (node (length, 0)) when nw is even.
Mesh strip(double length, double width, int nl, int nw);

}  // namespace spifit::mesh
