#include "forward/scenes/cone/cone_observables.hpp"

#include <algorithm>
#include <numbers>
#include <cmath>
#include <limits>
#include <utility>

namespace spifit::scene {

Eigen::Vector3d polar_components(const Eigen::Vector3d& force, const Eigen::Vector3d& position) {
  const double theta = std::atan2(position.y(), position.x());  // atan2(0, 0) = 0 on the axis
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * force.x() + s * force.y(), -s * force.x() + c * force.y(), force.z()};
}

ConeTrack::ConeTrack(toolpath::ConePath path) : path_(std::move(path)), distance_(path_.path.waypoint_distances()) {
  const auto& seg = path_.segments;
  for (std::size_t i = 1; i < seg.size(); ++i) {
    if (seg[i].move != toolpath::ConeMove::contour) continue;
    const bool same = !spans_.empty() && spans_.back().stage == seg[i].stage && spans_.back().contour == seg[i].contour;
    if (same) {
      spans_.back().end = distance_[i];
    } else {
      spans_.push_back({seg[i].stage, seg[i].contour, distance_[i - 1], distance_[i]});
    }
  }
}

const toolpath::ConeSegment& ConeTrack::segment_at(double s) const {
  const auto it = std::lower_bound(distance_.begin(), distance_.end(), s);
  const std::size_t i = it == distance_.end() ? distance_.size() - 1 : static_cast<std::size_t>(it - distance_.begin());
  return path_.segments[i];
}

int ConeTrack::completed(double s) const {
  int n = 0;
  for (const auto& c : spans_) n += c.end <= s + 1e-9 ? 1 : 0;
  return n;
}

double ConeTrack::min_axis_distance() const {
  double r = std::numeric_limits<double>::infinity();
  for (const auto& w : path_.path.waypoints()) r = std::min(r, w.position.head<2>().norm());
  return r;
}

std::vector<ContourMean> contour_means(const ConeTrack& track, const std::vector<ForceSample>& samples, int contours) {
  std::vector<ContourMean> out;
  const auto& spans = track.contours();
  for (std::size_t k = 0; k < spans.size() && static_cast<int>(k) < contours; ++k) {
    ContourMean m;
    m.span = spans[k];
    for (const auto& x : samples) {
      if (!m.span.central_third(x.s)) continue;
      ++m.samples;
      m.force += x.force;
      m.polar += x.polar;
    }
    const double n = m.samples > 0 ? static_cast<double>(m.samples) : std::numeric_limits<double>::quiet_NaN();
    m.force /= n;
    m.polar /= n;
    out.push_back(m);
  }
  return out;
}

SteadyState steady_state(const std::vector<ContourMean>& means, int from, int to) {
  SteadyState out;
  out.from = from;
  out.to = to;
  for (std::size_t k = 0; k < means.size(); ++k) {
    const int c = static_cast<int>(k) + 1;
    if (c < from || c > to || means[k].samples == 0) continue;
    out.force += means[k].force;
    out.polar += means[k].polar;
    ++out.contours;
  }
  const double n = out.contours > 0 ? static_cast<double>(out.contours) : std::numeric_limits<double>::quiet_NaN();
  out.force /= n;
  out.polar /= n;
  return out;
}

double section_angle_deg(double pie_angle_deg) {
  const double sectors = std::ceil(pie_angle_deg / 90.0 - 1e-9);  // as disc_mesh
  return 0.5 * pie_angle_deg / sectors;
}

std::vector<int> radial_line_nodes(const mesh::Mesh& m, double theta_deg) {
  const double t = theta_deg * std::numbers::pi / 180.0;
  const Eigen::Vector2d dir(std::cos(t), std::sin(t));
  double scale = 0.0;
  for (const auto& p : m.nodes) scale = std::max(scale, p.head<2>().norm());
  std::vector<std::pair<double, int>> line;
  for (int n = 0; n < m.num_nodes(); ++n) {
    const Eigen::Vector2d p = m.nodes[static_cast<std::size_t>(n)].head<2>();
    const double along = dir.dot(p), across = dir.x() * p.y() - dir.y() * p.x();
    if (std::abs(across) <= 1e-9 * scale && along >= -1e-9 * scale) line.emplace_back(along, n);
  }
  std::sort(line.begin(), line.end());
  std::vector<int> out;
  for (const auto& [r, n] : line) out.push_back(n);
  return out;
}

}  // namespace spifit::scene
