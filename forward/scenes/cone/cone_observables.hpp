#pragma once
// Observables of the cone scenes (thesis §8.3, §9.3): polar force components at the tool's polar angle,
// where the tool is along an annotated cone path (contour, move kind), and contour averages
// over the central third of each contour (thesis §8.3, footnote 8).
#include "forward/mesh/mesh.hpp"
#include "forward/toolpath/cone_path.hpp"

#include <Eigen/Core>

#include <vector>

namespace spifit::scene {

// (F_r, F_theta, F_z) of `force` in the polar frame at the polar angle theta of `position`
// (the tool centre): F_r = F_x cos(theta) + F_y sin(theta), F_theta = -F_x sin(theta) +
// F_y cos(theta). On the axis theta = 0.
Eigen::Vector3d polar_components(const Eigen::Vector3d& force, const Eigen::Vector3d& position);

// Travelled distances [mm] along a path where one contour starts and ends.
struct ContourSpan {
  int stage = 1, contour = 0;
  double start = 0.0, end = 0.0;
  // The central third of the contour (by travelled distance).
  bool central_third(double s) const { return s >= start + (end - start) / 3.0 && s <= start + 2.0 * (end - start) / 3.0; }
};

// Where the tool is along an annotated cone path.
class ConeTrack {
 public:
  explicit ConeTrack(toolpath::ConePath path);
  const toolpath::ConePath& path() const { return path_; }
  // The segment the tool is on at travelled distance s (the one ending at the first waypoint
  // at or beyond s; segments[0], the start, at s = 0).
  const toolpath::ConeSegment& segment_at(double s) const;
  // Contours in path order (for vwall: stage by stage).
  const std::vector<ContourSpan>& contours() const { return spans_; }
  // Number of contours whose end lies at or before s.
  int completed(double s) const;
  // Smallest horizontal distance of the tool centre from the axis over the path.
  double min_axis_distance() const;

 private:
  toolpath::ConePath path_;
  std::vector<double> distance_;  // per waypoint
  std::vector<ContourSpan> spans_;
};

// One output row of a cone run: travelled distance and the force on the tool.
struct ForceSample {
  double s = 0.0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // Cartesian
  Eigen::Vector3d polar = Eigen::Vector3d::Zero();  // (r, theta, z)
};

struct ContourMean {
  ContourSpan span;
  int samples = 0;  // samples in the central third
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), polar = Eigen::Vector3d::Zero();  // means (NaN without samples)
};

// Means of the samples in the central third of each of the first `contours` contours.
std::vector<ContourMean> contour_means(const ConeTrack& track, const std::vector<ForceSample>& samples, int contours);

// Steady state (thesis §9.3 uses contours 60-80 of the 100-contour cone70): the mean of
// the central-third means of contours `from`..`to` (1-based, path order), over those of them that
// are completed and have samples (`contours` says how many; 0: NaN means).
struct SteadyState {
  int from = 0, to = 0, contours = 0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), polar = Eigen::Vector3d::Zero();
};
SteadyState steady_state(const std::vector<ContourMean>& means, int from, int to);

// Shape section (thesis §8.2.1, §9.2): the nodes of the initial mesh on the radial line at the polar angle
// section_angle_deg(pie_angle), sorted by radius (the axis node first). The angle is the middle
// of the first O-grid sub-sector of disc_mesh, a line of nodes: the pie middle for pies up to
// 90 deg (22.5 deg for 45, 45 deg for 90), 45 deg for the full disc.
double section_angle_deg(double pie_angle_deg);
std::vector<int> radial_line_nodes(const mesh::Mesh& m, double theta_deg);

}  // namespace spifit::scene
