#pragma once
// Radial shape sections of a cone (thesis §8.2.1, §9.2; docs/design/cone.md "Shape, stage and element observables"): the nodes of
// the initial radial line at the pie middle (cone_observables.hpp, radial_line_nodes) in the
// current state, with
//  - the mid-surface point (r, theta, z) and the nodal thickness h;
//  - the top (tool-side) and bottom surfaces, mid +- h/2 along the nodal director (the shell's
//    director d of ShellModel::director, unit, rotated with the node; the contact surface is
//    offset along the same director, docs/design/contact.md), and the depth of the top surface below
//    its initial height t0/2 (thickness vs depth, thesis Figs. 9.8, 9.9);
//  - the wall angle of the mid-surface from the neighbouring section points;
//  - the twist (thesis §9.4.5, Fig. 9.41): circumferential displacement u_theta of each node
//    at its initial polar angle theta0, and the change of its polar angle;
//  - the radial elongation ratio of the element edges along the line (thesis §8.2.1,
//    Fig. 8.17 and its footnote 6): current over initial edge length;
//  - a summary: the wall-thickness plateau against the sine law t0 sin(90 deg - alpha).
#include <Eigen/Core>

#include <string>
#include <vector>

namespace spifit::scene {

// One node of the section line: its initial mid-surface point, current mid-surface point,
// current unit director and nodal thickness.
struct SectionNode {
  Eigen::Vector3d reference = Eigen::Vector3d::Zero(), position = Eigen::Vector3d::Zero();
  Eigen::Vector3d director = Eigen::Vector3d::UnitZ();
  double thickness = 0.0;
};

struct SectionPoint {
  double r0 = 0.0;                       // initial radius
  double r = 0.0, theta_deg = 0.0, z = 0.0;  // current mid-surface point (polar)
  double thickness = 0.0;
  double r_top = 0.0, z_top = 0.0;       // mid + h/2 d (the tool side)
  double r_bottom = 0.0, z_bottom = 0.0; // mid - h/2 d
  double depth = 0.0;                    // t0/2 - z_top: the top surface below its initial height
  double wall_angle_deg = 0.0;           // section_wall_angles
  double u_theta = 0.0;                  // -u_x sin(theta0) + u_y cos(theta0)
  double dtheta_deg = 0.0;               // current polar angle - theta0, in (-180, 180]; 0 on the axis
};

// The section a run takes after a completed contour: the contour's stage and number within the
// stage (ContourSpan), its points from the axis outwards.
struct ConeSection {
  int stage = 1, contour = 0;
  std::vector<SectionPoint> points;
  // A run with sensitivities: the derivatives of the points' r, z and thickness, one row per point
  // (in the order of `points`), one column per parameter; empty otherwise.
  Eigen::MatrixXd dr, dz, dthickness;
};

// The section points of `nodes` (sorted from the axis outwards) on the line at theta0_deg;
// t0 = initial thickness.
std::vector<SectionPoint> radial_section(const std::vector<SectionNode>& nodes, double theta0_deg, double t0);

// Angle [deg] from the horizontal of the polyline (r_i, z_i) at each point, from the chord
// between its neighbours (one-sided at the ends): atan2(z_{i+1} - z_{i-1}, r_{i+1} - r_{i-1}).
// A wall that rises outwards (a cone seen in its section) has a positive angle; 90 = vertical.
std::vector<double> section_wall_angles(const std::vector<double>& r, const std::vector<double>& z);

// Radial elongation (thesis Fig. 8.17): for each edge between consecutive section nodes, the
// current over the initial length of the mid-surface chord.
struct RadialEdge {
  double r0_inner = 0.0, r0_outer = 0.0;
  double initial_length = 0.0, length = 0.0, ratio = 0.0;
};
std::vector<RadialEdge> radial_elongation(const std::vector<SectionNode>& nodes);

// Wall-thickness plateau of a section: the mean thickness of the nodes whose wall angle lies
// within tolerance_deg of the cone's wall angle (NaN and 0 nodes when none does), compared with
// the sine law; the thinnest node of the section and where it is.
struct SectionSummary {
  double wall_angle_deg = 0.0, tolerance_deg = 5.0;
  int plateau_nodes = 0;
  double plateau_thickness = 0.0;
  double sine_law_thickness = 0.0;
  double min_thickness = 0.0, min_thickness_r0 = 0.0, min_thickness_depth = 0.0;
  double max_elongation = 0.0;  // largest RadialEdge ratio (0 without edges)
};
SectionSummary summarise_section(const std::vector<SectionPoint>& points, const std::vector<RadialEdge>& edges, double wall_angle_deg,
                                 double t0, double tolerance_deg = 5.0);

// CSV bodies (header row + rows; docs/reference/file-formats.md "Cone scene").
std::string section_csv(const std::vector<SectionPoint>& points);
std::string elongation_csv(const std::vector<RadialEdge>& edges);

}  // namespace spifit::scene
