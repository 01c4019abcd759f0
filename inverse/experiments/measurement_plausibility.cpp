#include "inverse/experiments/measurement_plausibility.hpp"

#include "forward/io/input_error.hpp"
#include "forward/material/hardening/hardening_laws.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace spifit::inverse {
namespace {

using namespace plausibility;

double largest_magnitude(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v)
    if (std::isfinite(x)) m = std::max(m, std::abs(x));
  return m;
}

// "96000 MPa": a value with its unit, three significant digits (whole numbers from 1000 on).
std::string amount(double v, const std::string& unit) {
  char buf[64];
  std::snprintf(buf, sizeof buf, std::abs(v) >= 1000.0 ? "%.0f" : "%.3g", v);
  return std::string(buf) + (unit.empty() || unit == "-" ? "" : " " + unit);
}

std::string times(double ratio) {
  char buf[32];
  std::snprintf(buf, sizeof buf, ratio >= 1000.0 ? "%.0f" : "%.2g", ratio);
  return buf;
}

// A scene input, or NaN when the scene has none of that name.
double input_or_nan(const scene::Scene& s, const std::string& name) {
  try {
    return s.input(name);
  } catch (const std::invalid_argument&) {
    return std::nan("");
  }
}

}  // namespace

MagnitudeCheck compare_magnitudes(const ExperimentCurve& c) {
  const double m = largest_magnitude(c.measured), s = largest_magnitude(c.simulated);
  if (!(m > 0.0) || !(s > 0.0)) return {};
  const double ratio = std::max(m / s, s / m);
  if (ratio < kOddRatio) return {};
  const std::string what = c.y_name.empty() ? "values" : c.y_name + " values";
  const std::string message = "measured " + what + " reach " + amount(m, c.y_unit) + ", " + times(ratio) + " times " +
                              (m > s ? "more" : "less") + " than the start card gives (" + amount(s, c.y_unit) + ")" +
                              (ratio >= kImplausibleRatio ? ": is the unit in the data file's header right?" : "");
  return {ratio >= kImplausibleRatio ? 2 : 1, message};
}

MagnitudeCheck fe_magnitudes(const std::string& y, const std::string& unit, const std::vector<double>& measured, const scene::Scene& scene,
                             const material::MaterialParams<double>& m) {
  const double v = largest_magnitude(measured);
  if (!(v > 0.0)) return {};
  const double t = input_or_nan(scene, "sheet.thickness"), radius = input_or_nan(scene, "tool.radius");
  char buf[400];
  if (unit == "N" && std::isfinite(t) && std::isfinite(radius)) {
    const double flow = m.plastic ? material::hardening_stress(m, 0.2) : 0.01 * m.E;
    const double scale = flow * t * radius;
    if (scale > 0.0 && v > kForceScaleImplausible * scale) {
      std::snprintf(buf, sizeof buf,
                    "measured forces reach %s, %s times the force scale of this sheet and tool (flow stress %s x thickness %s x tool "
                    "radius %s = %s): is the unit in the data file's header right?",
                    amount(v, "N").c_str(), times(v / scale).c_str(), amount(flow, "MPa").c_str(), amount(t, "mm").c_str(),
                    amount(radius, "mm").c_str(), amount(scale, "N").c_str());
      return {2, buf};
    }
    return {};
  }
  if (y.find("_over_") != std::string::npos) {
    if (v > kRatioImplausible) return {2, "measured force ratios reach " + amount(v, "") + ": a ratio of two force components of a forming tool stays near 1"};
    return {};
  }
  if (y == "thickness" && std::isfinite(t)) {
    const double ratio = std::max(v / t, t / v);
    if (ratio > kOddRatio) {
      std::snprintf(buf, sizeof buf, "measured thicknesses reach %s against a sheet of %s: is the unit in the data file's header right?",
                    amount(v, "mm").c_str(), amount(t, "mm").c_str());
      return {2, buf};
    }
    return {};
  }
  if (y == "z") {
    const auto path = scene.tool_centre_path();
    if (!path) return {};
    // The tool tip's depth below the initial top surface: the centre starts t/2 + R above the
    // mid-surface. The sheet's mid-surface cannot be much deeper than the tip went.
    const double half = std::isfinite(t) ? 0.5 * t : 0.0, r = std::isfinite(radius) ? radius : 0.0;
    double depth = 0.0;
    for (const auto& w : path->waypoints()) depth = std::max(depth, half + r - w.position.z());
    const double reach = depth + 2.0 * half;
    if (reach > 0.0 && v > kOddRatio * reach) {
      std::snprintf(buf, sizeof buf,
                    "measured heights reach %s, while the tool never goes deeper than %s: is the unit in the data file's header right?",
                    amount(v, "mm").c_str(), amount(reach, "mm").c_str());
      return {2, buf};
    }
  }
  return {};
}

MagnitudeCheck Experiment::check_magnitudes(const ParameterPoint& start) const { return compare_magnitudes(compare(start)); }

}  // namespace spifit::inverse
