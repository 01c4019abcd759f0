#include "forward/toolpath/cone_path.hpp"

#include "forward/io/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace spifit::toolpath {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMaxWaypoints = 1e7;  // guards against absurd chord tolerances

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("cone path: " + what);
}

std::string num(double v) { return io::format_number(v); }

double radians(double deg) { return deg * kPi / 180.0; }

// sin, cos and 1/tan of the wall angle; exact for the vertical wall (cos = 1/tan = 0).
struct Wall {
  double sin, cos, cot;
};
Wall wall(const ConePathOptions& o) {
  if (o.wall_angle_deg == 90.0) return {1.0, 0.0, 0.0};
  const double a = radians(o.wall_angle_deg);
  return {std::sin(a), std::cos(a), std::cos(a) / std::sin(a)};
}

bool full_disc(const ConePathOptions& o) { return o.pie_angle_deg == 360.0; }

// Geometry without checks (see the header comment for the formulas).
double touch_z(const ConePathOptions& o, int k) {
  return 0.5 * o.thickness - static_cast<double>(k) * o.stepdown;
}
double touch_r(const ConePathOptions& o, int k) {
  return o.top_radius - static_cast<double>(k) * o.stepdown * wall(o).cot;
}
double centre_r(const ConePathOptions& o, int k) {
  return touch_r(o, k) - o.tool_radius * wall(o).sin;
}
double centre_z(const ConePathOptions& o, int k) {
  return touch_z(o, k) + o.tool_radius * wall(o).cos;
}
double approach_z(const ConePathOptions& o) {
  return 0.5 * o.thickness + o.approach_clearance + o.tool_radius;
}

// The stepdown ramp from contour k to k+1 (full disc), parametrised by its horizontal arc
// length s in [0, length]: r = r_c(k) + slope_r s, z = z_c(k) - tan(ramp) s and a constant
// heading, so dtheta/ds = sqrt(1 - slope_r^2) / r (a logarithmic spiral on the tool-centre
// cone; slope_r = dr/ds = -tan(ramp) / tan(alpha), |slope_r| < 1 as ramp < alpha).
struct Ramp {
  double r0, z0, tan_ramp, slope_r, length;
  double radius(double s) const { return r0 + slope_r * s; }
  double z(double s) const { return z0 - tan_ramp * s; }
  double theta(double s) const {  // swept angle, rad, >= 0
    const double tangential = std::sqrt(1.0 - slope_r * slope_r);
    if (slope_r == 0.0) return tangential * s / r0;
    return tangential * std::log1p(slope_r * s / r0) / slope_r;
  }
};
Ramp ramp(const ConePathOptions& o, int k) {
  const double tan_ramp = std::tan(radians(o.ramp_angle_deg));
  return Ramp{centre_r(o, k), centre_z(o, k), tan_ramp, -tan_ramp * wall(o).cot,
              o.stepdown / tan_ramp};
}

// Number of chords of an arc of radius r sweeping |sweep| rad with sagitta
// r (1 - cos(phi / 2)) = 2 r sin^2(phi / 4) <= tol; at most a quarter turn per chord.
double arc_chords(double r, double sweep, double tol) {
  double phi = kPi / 2.0;
  const double x = tol / (2.0 * r);
  if (x < 1.0) phi = std::min(phi, 4.0 * std::asin(std::sqrt(x)));
  return std::max(1.0, std::ceil(std::abs(sweep) / phi));
}

// Chords of a ramp: a chord of horizontal arc length ds on a curve whose radius of curvature
// is >= r_min (the spiral's is r / sqrt(1 - slope_r^2) >= r) has a sagitta <= tol when ds is at
// most the chord 2 sqrt(2 r_min tol - tol^2) of a circle of radius r_min with that sagitta.
// The ramp is vertical-linear in s, so the sagitta is horizontal only.
double ramp_chords(const Ramp& rp, double tol) {
  const double r_min = std::min(rp.radius(0.0), rp.radius(rp.length));
  double n = arc_chords(r_min, rp.theta(rp.length), tol);  // also caps a quarter turn
  if (tol < r_min)
    n = std::max(n, std::ceil(rp.length / (2.0 * std::sqrt(2.0 * r_min * tol - tol * tol))));
  return n;
}

void check_k(const ConePathOptions& o, int k, int lo, int hi, const char* what) {
  check_cone_path_options(o);
  if (k < lo || k > hi)
    fail(std::string(what) + ": k = " + std::to_string(k) + " must lie in [" +
         std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

Eigen::Vector3d polar(double r, double theta, double z) {
  return {r * std::cos(theta), r * std::sin(theta), z};
}

class Builder {
 public:
  // Appends p reached at feed; a point equal to the last one is skipped (no zero-length
  // segments).
  void add(const Eigen::Vector3d& p, double feed, ConeSegment tag) {
    if (!points_.empty() && p == points_.back().position) return;
    points_.push_back(Waypoint{p, feed, 0});
    tags_.push_back(tag);
  }
  // Arc of radius r at height z from theta0 (the current point) over the signed sweep;
  // returns the angle of its last point.
  double arc(double r, double z, double theta0, double sweep, double tol, double feed,
             ConeSegment tag) {
    const auto n = static_cast<long>(arc_chords(r, sweep, tol));
    for (long i = 1; i <= n; ++i)
      add(polar(r, theta0 + sweep * (static_cast<double>(i) / static_cast<double>(n)), z), feed,
          tag);
    return theta0 + sweep;
  }
  bool empty() const { return points_.empty(); }
  const Eigen::Vector3d& last() const { return points_.back().position; }
  ConePath finish() && {
    return ConePath{ToolPath(std::move(points_)), std::move(tags_)};
  }

 private:
  std::vector<Waypoint> points_;
  std::vector<ConeSegment> tags_;
};

// Appends one cone (one stage) to b; its first point is the start (or, after a previous
// stage, the descent to this stage's approach height).
void append_cone(const ConePathOptions& o, int stage, Builder& b) {
  const int n = o.contours;
  const double dir = o.counter_clockwise ? 1.0 : -1.0;
  const double tol = o.chord_tolerance, f = o.feed, z_app = approach_z(o);
  const auto tag = [stage](ConeMove m, int k) { return ConeSegment{m, stage, k}; };

  const double theta_start = full_disc(o) ? radians(o.stepdown_angle_deg)
                             : o.counter_clockwise ? 0.0
                                                   : radians(o.pie_angle_deg);
  b.add(polar(centre_r(o, 1), theta_start, z_app), f,
        tag(b.empty() ? ConeMove::start : ConeMove::stage_change, 0));
  b.add(polar(centre_r(o, 1), theta_start, centre_z(o, 1)), f, tag(ConeMove::approach, 1));

  double theta_end = theta_start;
  if (full_disc(o)) {
    theta_end = b.arc(centre_r(o, 1), centre_z(o, 1), theta_start, dir * 2.0 * kPi, tol, f,
                      tag(ConeMove::contour, 1));
    for (int k = 1; k < n; ++k) {
      const Ramp rp = ramp(o, k);
      const double sweep = rp.theta(rp.length);
      const auto m = static_cast<long>(ramp_chords(rp, tol));
      for (long i = 1; i < m; ++i) {
        const double s = rp.length * static_cast<double>(i) / static_cast<double>(m);
        b.add(polar(rp.radius(s), theta_start + dir * rp.theta(s), rp.z(s)), f,
              tag(ConeMove::ramp, k + 1));
      }
      // End exactly on contour k+1 (no round-off from the parametrisation).
      const double theta_k = theta_start + dir * sweep;
      b.add(polar(centre_r(o, k + 1), theta_k, centre_z(o, k + 1)), f,
            tag(ConeMove::ramp, k + 1));
      const double turn = k + 1 == n ? 2.0 * kPi : 2.0 * kPi - sweep;
      theta_end = b.arc(centre_r(o, k + 1), centre_z(o, k + 1), theta_k, dir * turn, tol, f,
                        tag(ConeMove::contour, k + 1));
    }
  } else {
    const double sweep = dir * radians(o.pie_angle_deg);
    for (int k = 1; k <= n; ++k) {
      theta_end = b.arc(centre_r(o, k), centre_z(o, k), theta_start, sweep, tol, f,
                        tag(ConeMove::contour, k));
      if (k == n) break;
      const double z_lift = centre_z(o, k) + o.lift;
      b.add(polar(centre_r(o, k), theta_end, z_lift), f, tag(ConeMove::lift, k + 1));
      b.add(polar(centre_r(o, k + 1), theta_start, z_lift), f, tag(ConeMove::move, k + 1));
      b.add(polar(centre_r(o, k + 1), theta_start, centre_z(o, k + 1)), f,
            tag(ConeMove::plunge, k + 1));
    }
  }
  b.add(polar(centre_r(o, n), theta_end, z_app), f, tag(ConeMove::retract, n));
}

}  // namespace

void check_cone_path_options(const ConePathOptions& o) {
  const auto positive = [](double v, const char* name) {
    if (!std::isfinite(v) || !(v > 0.0)) fail(std::string(name) + " = " + num(v) + " must be > 0");
  };
  if (!(o.wall_angle_deg > 0.0 && o.wall_angle_deg <= 90.0))
    fail("wall_angle_deg = " + num(o.wall_angle_deg) + " must lie in (0, 90]");
  positive(o.stepdown, "stepdown");
  if (o.contours < 1) fail("contours = " + std::to_string(o.contours) + " must be >= 1");
  positive(o.top_radius, "top_radius");
  positive(o.thickness, "thickness");
  positive(o.tool_radius, "tool_radius");
  if (!(o.pie_angle_deg > 0.0 && o.pie_angle_deg <= 360.0))
    fail("pie_angle_deg = " + num(o.pie_angle_deg) + " must lie in (0, 360]");
  if (!std::isfinite(o.stepdown_angle_deg))
    fail("stepdown_angle_deg = " + num(o.stepdown_angle_deg) + " must be finite");
  if (full_disc(o) && !(o.ramp_angle_deg > 0.0 && o.ramp_angle_deg < o.wall_angle_deg))
    fail("ramp_angle_deg = " + num(o.ramp_angle_deg) + " must lie in (0, wall_angle_deg = " +
         num(o.wall_angle_deg) + ")");
  positive(o.feed, "feed");
  if (!full_disc(o)) positive(o.lift, "lift");
  positive(o.chord_tolerance, "chord_tolerance");
  if (!std::isfinite(o.approach_clearance) || o.approach_clearance < 0.0)
    fail("approach_clearance = " + num(o.approach_clearance) + " must be >= 0");

  const double r_last = centre_r(o, o.contours);
  if (!(r_last > 0.0))
    fail("contours = " + std::to_string(o.contours) + " with stepdown = " + num(o.stepdown) +
         " reach the axis: the tool centre's radius at the last contour would be " +
         num(r_last) + " mm (r_top - N stepdown / tan(alpha) - R sin(alpha) must be > 0)");

  // Size of the path (and, for the full disc, the length of the ramps) before building it.
  const double sweep = full_disc(o) ? 2.0 * kPi : radians(o.pie_angle_deg);
  double points = 2.0;
  for (int k = 1; k <= o.contours; ++k) {
    points += arc_chords(centre_r(o, k), sweep, o.chord_tolerance) + 3.0;
    if (points > kMaxWaypoints) break;
    if (!full_disc(o) || k == o.contours) continue;
    const Ramp rp = ramp(o, k);
    const double ramp_sweep = rp.theta(rp.length);
    if (!(ramp_sweep <= kPi))
      fail("ramp_angle_deg = " + num(o.ramp_angle_deg) + " makes the ramp from contour " +
           std::to_string(k) + " to " + std::to_string(k + 1) + " sweep " +
           num(ramp_sweep * 180.0 / kPi) + " deg (at most 180)");
    points += ramp_chords(rp, o.chord_tolerance);
    if (points > kMaxWaypoints) break;
  }
  if (!(points <= kMaxWaypoints))
    fail("chord_tolerance = " + num(o.chord_tolerance) + " mm needs about " + num(points) +
         " waypoints (at most " + num(kMaxWaypoints) + ")");
}

double cone_contour_centre_radius(const ConePathOptions& o, int k) {
  check_k(o, k, 0, o.contours, "cone_contour_centre_radius");
  return centre_r(o, k);
}
double cone_contour_centre_z(const ConePathOptions& o, int k) {
  check_k(o, k, 0, o.contours, "cone_contour_centre_z");
  return centre_z(o, k);
}
double cone_contour_touch_radius(const ConePathOptions& o, int k) {
  check_k(o, k, 0, o.contours, "cone_contour_touch_radius");
  return touch_r(o, k);
}
double cone_contour_touch_z(const ConePathOptions& o, int k) {
  check_k(o, k, 0, o.contours, "cone_contour_touch_z");
  return touch_z(o, k);
}
double cone_approach_centre_z(const ConePathOptions& o) {
  check_cone_path_options(o);
  return approach_z(o);
}
double cone_ramp_sweep(const ConePathOptions& o, int k) {
  if (!full_disc(o)) fail("cone_ramp_sweep: only full discs (pie_angle_deg = 360) have ramps");
  check_k(o, k, 1, o.contours - 1, "cone_ramp_sweep");
  const Ramp rp = ramp(o, k);
  return rp.theta(rp.length);
}

ConePath annotated_cone_path(const ConePathOptions& o) {
  check_cone_path_options(o);
  Builder b;
  append_cone(o, 1, b);
  return std::move(b).finish();
}

ToolPath cone_path(const ConePathOptions& o) { return annotated_cone_path(o).path; }

ConePath annotated_multistage_cone_path(const std::vector<ConePathOptions>& stages,
                                        double safe_z) {
  const std::string what = "multistage cone path: ";
  if (stages.empty()) throw std::invalid_argument(what + "no stages");
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const std::string stage = "stage " + std::to_string(i + 1) + ": ";
    try {
      check_cone_path_options(stages[i]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(what + stage + e.what());
    }
    if (!std::isfinite(safe_z) || !(safe_z >= approach_z(stages[i])))
      throw std::invalid_argument(what + "safe_z = " + num(safe_z) + " must be >= " +
                                  num(approach_z(stages[i])) + " (" + stage +
                                  "approach height of the tool centre)");
  }
  Builder b;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const int stage = static_cast<int>(i) + 1;
    if (i > 0) {
      // Up to safe_z, across to above the next stage's first point; append_cone descends.
      const ConePathOptions& o = stages[i];
      const double theta = full_disc(o) ? radians(o.stepdown_angle_deg)
                           : o.counter_clockwise ? 0.0
                                                 : radians(o.pie_angle_deg);
      const Eigen::Vector3d above = polar(centre_r(o, 1), theta, safe_z);
      const Eigen::Vector3d here = b.last();
      const ConeSegment tag{ConeMove::stage_change, stage, 0};
      b.add({here.x(), here.y(), safe_z}, stages[i - 1].feed, tag);
      b.add(above, o.feed, tag);
    }
    append_cone(stages[i], stage, b);
  }
  return std::move(b).finish();
}

ToolPath multistage_cone_path(const std::vector<ConePathOptions>& stages, double safe_z) {
  return annotated_multistage_cone_path(stages, safe_z).path;
}

ConePathOptions cone50(double pie_deg) {
  ConePathOptions o;
  o.wall_angle_deg = 50.0;
  o.stepdown = 1.0;
  o.contours = 30;
  o.top_radius = 64.0;
  o.thickness = 1.5;
  o.tool_radius = 5.0;
  o.pie_angle_deg = pie_deg;
  o.stepdown_angle_deg = 6.0;
  return o;
}

ConePathOptions cone70(int contours, double pie_deg) {
  ConePathOptions o;
  o.wall_angle_deg = 70.0;
  o.stepdown = 0.5;
  o.contours = contours;
  o.top_radius = 90.0;
  o.thickness = 1.2;
  o.tool_radius = 5.0;
  o.pie_angle_deg = pie_deg;
  o.stepdown_angle_deg = 0.0;
  return o;
}

std::vector<ConePathOptions> vwall_stages(double pie_deg) {
  const double angles[] = {50.0, 60.0, 70.0, 80.0, 90.0};
  const double stepdowns[] = {6.0, -177.0, -118.0, 43.0, -45.0};  // thesis §8.1.1 footnote 1
  std::vector<ConePathOptions> stages;
  for (int i = 0; i < 5; ++i) {
    ConePathOptions o = cone50(pie_deg);
    o.wall_angle_deg = angles[i];
    o.stepdown_angle_deg = stepdowns[i];
    stages.push_back(o);
  }
  return stages;
}

}  // namespace spifit::toolpath
