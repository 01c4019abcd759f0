#include "inverse/experiments/scan_section.hpp"

#include "forward/io/csv_writer.hpp"
#include "forward/io/input_error.hpp"
#include "inverse/experiments/measurement.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace spifit::inverse {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// Unit normals of the polyline of bin means, on the tool side: the side of (-1, 1) in (r, z), so
// that a wall of angle alpha in [0, 90] deg gets (-sin alpha, cos alpha) whichever way the bins
// run (a vertical wall: towards the axis, also with noise).
std::vector<Eigen::Vector2d> section_normals(const std::vector<Eigen::Vector2d>& p) {
  std::vector<Eigen::Vector2d> n(p.size(), Eigen::Vector2d(0.0, 1.0));
  if (p.size() < 2) return n;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == p.size() ? i : i + 1;
    const Eigen::Vector2d t = p[hi] - p[lo];
    if (!(t.norm() > 0.0)) continue;
    Eigen::Vector2d v(-t.y(), t.x());
    v.normalize();
    if (v.y() - v.x() < 0.0) v = -v;
    n[i] = v;
  }
  return n;
}

}  // namespace

std::vector<Eigen::Vector3d> read_scan_cloud(const std::string& path) {
  const MeasurementTable t = read_measurement_csv(path);
  const auto& x = t.column("x");
  const auto& y = t.column("y");
  const auto& z = t.column("z");
  std::vector<Eigen::Vector3d> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) out[i] = Eigen::Vector3d(x[i], y[i], z[i]);
  return out;
}

std::string ScanSectionOptions::validate() const {
  const auto bad = [](const std::string& key, double v, const std::string& what) { return key + " = " + io::format_number(v) + ": " + what; };
  if (!(bin > 0.0 && std::isfinite(bin))) return bad("bin", bin, "must be > 0");
  if (binning == ScanBinning::angle && !(bin <= 90.0)) return bad("bin", bin, "an angle bin must be at most 90 deg");
  if (!std::isfinite(origin_z)) return bad("origin_z", origin_z, "must be finite");
  if (min_points < 1) return bad("min_points", min_points, "must be >= 1");
  if (!(band > 0.0 && band < 1.0)) return bad("band", band, "must lie in (0, 1)");
  if (!std::isfinite(shift_thickness)) return bad("shift_thickness", shift_thickness, "must be finite");
  return "";
}

double sorted_quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return std::nan("");
  const double h = q * static_cast<double>(sorted.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  if (lo + 1 >= sorted.size()) return sorted.back();
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[lo + 1] - sorted[lo]);
}

ScanSection average_scan_section(const std::vector<Eigen::Vector3d>& cloud, const ScanSectionOptions& o) {
  if (const std::string err = o.validate(); !err.empty()) throw std::invalid_argument(err);
  const bool by_angle = o.binning == ScanBinning::angle;
  std::map<long long, std::vector<Eigen::Vector2d>> groups;  // bin index -> (r, z) of its points
  for (const auto& p : cloud) {
    const Eigen::Vector2d rz(p.head<2>().norm(), p.z());
    const double key = by_angle ? std::atan2(rz.x(), rz.y() - o.origin_z) * kDeg : rz.x();
    groups[static_cast<long long>(std::floor(key / o.bin))].push_back(rz);
  }
  ScanSection s;
  s.points = static_cast<int>(cloud.size());
  const Eigen::Vector2d origin(0.0, o.origin_z);
  for (const auto& [index, pts] : groups) {
    if (static_cast<int>(pts.size()) < o.min_points) {
      ++s.bins_left_out;
      continue;
    }
    ScanBin b;
    b.lower = static_cast<double>(index) * o.bin;
    b.upper = b.lower + o.bin;
    b.points = static_cast<int>(pts.size());
    for (const auto& q : pts) b.mean += q;
    b.mean /= static_cast<double>(pts.size());
    // The spread coordinate: z across a radius bin, the distance from the origin along a ray.
    const Eigen::Vector2d ray = (b.mean - origin).normalized();
    std::vector<double> v;
    v.reserve(pts.size());
    for (const auto& q : pts) v.push_back(by_angle ? (q - origin).norm() : q.y());
    double mean = 0.0, var = 0.0;
    for (double x : v) mean += x;
    mean /= static_cast<double>(v.size());
    for (double x : v) var += (x - mean) * (x - mean);
    b.spread_std = v.size() > 1 ? std::sqrt(var / static_cast<double>(v.size() - 1)) : 0.0;
    std::sort(v.begin(), v.end());
    const double lo = sorted_quantile(v, 0.5 * (1.0 - o.band)), hi = sorted_quantile(v, 0.5 * (1.0 + o.band));
    int inside = 0;
    for (double x : v) inside += x >= lo && x <= hi ? 1 : 0;
    b.inside = static_cast<double>(inside) / static_cast<double>(v.size());
    if (by_angle) {
      b.band_low = origin + lo * ray;
      b.band_high = origin + hi * ray;
    } else {
      b.band_low = Eigen::Vector2d(b.mean.x(), lo);
      b.band_high = Eigen::Vector2d(b.mean.x(), hi);
    }
    s.points_used += b.points;
    s.bins.push_back(b);
  }
  if (s.bins.empty())
    throw std::invalid_argument("no bin holds " + std::to_string(o.min_points) + " points (" + std::to_string(cloud.size()) +
                                " points; a wider --bin or a smaller --min-points may help)");
  if (o.shift != ScanShift::none && o.shift_thickness != 0.0) {
    std::vector<Eigen::Vector2d> means;
    for (const auto& b : s.bins) means.push_back(b.mean);
    const std::vector<Eigen::Vector2d> n = section_normals(means);
    for (std::size_t i = 0; i < s.bins.size(); ++i) {
      const Eigen::Vector2d d = 0.5 * o.shift_thickness * (o.shift == ScanShift::vertical ? Eigen::Vector2d(0.0, 1.0) : n[i]);
      s.bins[i].mean += d;
      s.bins[i].band_low += d;
      s.bins[i].band_high += d;
    }
  }
  return s;
}

std::string scan_section_csv(const ScanSection& s, const ScanSectionOptions& o) {
  const std::string unit = o.binning == ScanBinning::angle ? " [deg]" : " [mm]";
  io::CsvTable t({"bin_lower" + unit, "bin_upper" + unit, "points", "r [mm]", "z [mm]", "std [mm]", "r_low [mm]", "z_low [mm]", "r_high [mm]",
                  "z_high [mm]", "inside"});
  for (const auto& b : s.bins)
    t.add_row({b.lower, b.upper, static_cast<double>(b.points), b.mean.x(), b.mean.y(), b.spread_std, b.band_low.x(), b.band_low.y(),
               b.band_high.x(), b.band_high.y(), b.inside});
  return t.str();
}

}  // namespace spifit::inverse
