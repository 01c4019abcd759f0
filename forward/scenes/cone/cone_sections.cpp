#include "forward/scenes/cone/cone_sections.hpp"

#include "forward/io/csv_writer.hpp"
#include "forward/scenes/cone/sine_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace spifit::scene {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

}  // namespace

std::vector<SectionPoint> radial_section(const std::vector<SectionNode>& nodes, double theta0_deg, double t0) {
  const double t0r = theta0_deg / kDeg, c0 = std::cos(t0r), s0 = std::sin(t0r);
  double scale = 0.0;
  for (const auto& n : nodes) scale = std::max(scale, n.reference.head<2>().norm());
  std::vector<SectionPoint> out;
  std::vector<double> r, z;
  for (const auto& n : nodes) {
    SectionPoint p;
    const Eigen::Vector3d& x = n.position;
    const Eigen::Vector3d top = x + 0.5 * n.thickness * n.director, bottom = x - 0.5 * n.thickness * n.director;
    const Eigen::Vector3d u = x - n.reference;
    p.r0 = n.reference.head<2>().norm();
    p.r = x.head<2>().norm();
    p.theta_deg = std::atan2(x.y(), x.x()) * kDeg;
    p.z = x.z();
    p.thickness = n.thickness;
    p.r_top = top.head<2>().norm();
    p.z_top = top.z();
    p.r_bottom = bottom.head<2>().norm();
    p.z_bottom = bottom.z();
    p.depth = 0.5 * t0 - p.z_top;
    p.u_theta = -u.x() * s0 + u.y() * c0;
    // The polar angle of a node on (or at) the axis is undefined: no angle change there.
    if (p.r > 1e-12 * std::max(scale, 1.0) && p.r0 > 1e-12 * std::max(scale, 1.0)) {
      double d = p.theta_deg - theta0_deg;
      d = std::remainder(d, 360.0);  // (-180, 180]
      p.dtheta_deg = d == -180.0 ? 180.0 : d;
    }
    r.push_back(p.r);
    z.push_back(p.z);
    out.push_back(p);
  }
  const std::vector<double> a = section_wall_angles(r, z);
  for (std::size_t i = 0; i < out.size(); ++i) out[i].wall_angle_deg = a[i];
  return out;
}

std::vector<double> section_wall_angles(const std::vector<double>& r, const std::vector<double>& z) {
  const std::size_t n = std::min(r.size(), z.size());
  std::vector<double> a(n, std::numeric_limits<double>::quiet_NaN());
  if (n < 2) return a;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == n ? n - 1 : i + 1;
    a[i] = std::atan2(z[hi] - z[lo], r[hi] - r[lo]) * kDeg;
  }
  return a;
}

std::vector<RadialEdge> radial_elongation(const std::vector<SectionNode>& nodes) {
  std::vector<RadialEdge> out;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    RadialEdge e;
    e.r0_inner = nodes[i].reference.head<2>().norm();
    e.r0_outer = nodes[i + 1].reference.head<2>().norm();
    e.initial_length = (nodes[i + 1].reference - nodes[i].reference).norm();
    e.length = (nodes[i + 1].position - nodes[i].position).norm();
    e.ratio = e.length / e.initial_length;
    out.push_back(e);
  }
  return out;
}

SectionSummary summarise_section(const std::vector<SectionPoint>& points, const std::vector<RadialEdge>& edges, double wall_angle_deg,
                                 double t0, double tolerance_deg) {
  SectionSummary s;
  s.wall_angle_deg = wall_angle_deg;
  s.tolerance_deg = tolerance_deg;
  s.sine_law_thickness = sine_law_thickness(t0, wall_angle_deg);
  double sum = 0.0;
  s.min_thickness = std::numeric_limits<double>::infinity();
  for (const auto& p : points) {
    if (std::abs(p.wall_angle_deg - wall_angle_deg) <= tolerance_deg) {
      ++s.plateau_nodes;
      sum += p.thickness;
    }
    if (p.thickness < s.min_thickness) {
      s.min_thickness = p.thickness;
      s.min_thickness_r0 = p.r0;
      s.min_thickness_depth = p.depth;
    }
  }
  s.plateau_thickness = s.plateau_nodes > 0 ? sum / s.plateau_nodes : std::numeric_limits<double>::quiet_NaN();
  if (points.empty()) s.min_thickness = std::numeric_limits<double>::quiet_NaN();
  for (const auto& e : edges) s.max_elongation = std::max(s.max_elongation, e.ratio);
  return s;
}

std::string section_csv(const std::vector<SectionPoint>& points) {
  io::CsvTable t({"r0 [mm]", "r [mm]", "theta [deg]", "z [mm]", "thickness [mm]", "r_top [mm]", "z_top [mm]", "r_bottom [mm]",
                  "z_bottom [mm]", "depth [mm]", "wall_angle [deg]", "u_theta [mm]", "dtheta [deg]"});
  for (const auto& p : points)
    t.add_row({p.r0, p.r, p.theta_deg, p.z, p.thickness, p.r_top, p.z_top, p.r_bottom, p.z_bottom, p.depth, p.wall_angle_deg, p.u_theta,
               p.dtheta_deg});
  return t.str();
}

std::string elongation_csv(const std::vector<RadialEdge>& edges) {
  io::CsvTable t({"r0_inner [mm]", "r0_outer [mm]", "initial_length [mm]", "length [mm]", "ratio"});
  for (const auto& e : edges) t.add_row({e.r0_inner, e.r0_outer, e.initial_length, e.length, e.ratio});
  return t.str();
}

}  // namespace spifit::scene
