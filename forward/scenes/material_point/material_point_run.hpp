#pragma once
// Material-point experiments (thesis App. C): tensile (uniaxial stress at angle alpha to RD),
// shear and bauschinger (simple shear, with reversals), plane_strain and biaxial (given
// stress ratio). Plane stress, strain-controlled along a piecewise-linear path of the control
// strain, recorded at every increment. Templated on the scalar type (double or ceres::Jet).
#include "forward/scenes/material_point/material_point_driver.hpp"

#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace spifit::scene {

enum class MaterialPointKind { tensile, shear, bauschinger, plane_strain, biaxial };

std::string to_string(MaterialPointKind k);
bool material_point_kind_from_string(const std::string& s, MaterialPointKind* k);

struct MaterialPointSetup {
  MaterialPointKind kind = MaterialPointKind::tensile;
  double angle_deg = 0.0;             // loading direction from RD
  double stress_ratio = 1.0;          // biaxial: sigma_ww / sigma_ll
  std::vector<double> strain_path{0.3};  // targets of the control strain, from 0
  int increments = 200;               // recorded increments over the whole path
  double r_value_strain = 0.10;       // tensile: strain at which r is evaluated
  double offset_strain = 0.002;       // tensile: axial plastic strain of the offset yield stress
  bool want_r_value = true;           // tensile: evaluate the r-value (costs one side run)
  bool want_offset_yield = true;      // tensile: search the offset yield stress (costs ~15 side runs)
  DriverOptions driver;
};

LoadingControl loading_control(const MaterialPointSetup& setup);

template <typename T>
struct CurvePoint {
  int increment = 0;
  int segment = 0;
  double control_strain = 0.0;  // "strain": eps_ll (tensile, plane strain, biaxial) or gamma_lw (shear)
  double cumulative_strain = 0.0;  // sum of |d control strain| (monotone abscissa for reversals)
  T stress{};                    // true (Cauchy) stress of the control component [MPa]
  T stress_kirchhoff{};
  Eigen::Matrix<T, 3, 1> strain_loading;   // eps_ll, eps_ww, gamma_lw
  T thickness_strain{};
  Eigen::Matrix<T, 3, 1> stress_material;  // Cauchy sxx, syy, sxy in material axes
  Eigen::Matrix<T, 3, 1> plastic_strain;   // eps_p_xx, eps_p_yy, gamma_p_xy (material axes)
  Eigen::Matrix<T, 4, 1> back_stress;      // Xxx, Xyy, Xzz, Xxy (full tensor, material axes)
  T eqps{};
};

template <typename T>
struct MaterialPointResult {
  bool ok = true;
  std::string message;
  std::vector<CurvePoint<T>> curve;
  std::vector<YieldEvent<T>> yield_events;
  std::optional<T> r_value;  // tensile: width/thickness plastic strain-rate ratio at r_value_strain
  std::optional<T> offset_yield_stress;            // true stress at offset_strain axial plastic strain
  std::optional<T> offset_yield_stress_kirchhoff;
  double offset_yield_strain = 0.0;                // total axial strain there
  int substeps = 0, cutbacks = 0, newton_iterations = 0;
  int accuracy_limited_substeps = 0;  // sub-steps past DriverOptions::max_substeps (bound waived)
};

// Throws std::invalid_argument for a setup that makes no sense (checked before by the scene
// reader, which reports file and key).
void check_setup(const MaterialPointSetup& setup);

template <typename T>
T axial_plastic_strain(const MaterialPointDriver<T>& drv, const PointState<T>& s) {
  return drv.to_loading_strain(s.material.plastic_strain)(0);
}

// Solves eps_p_ll(x) = offset for the control increment x in [0, d] from the state `before`
// (Illinois regula falsi on exact re-runs of the increment) and stores the stress there.
// With Jets, the root's own parameter dependence is added:
//   d sigma/dp = partial + (d sigma/dx)(dx/dp),  dx/dp = -(dg/dp)/(dg/dx).
template <typename T>
void find_offset_yield(MaterialPointDriver<T>& drv, const PointState<T>& before, double d, double offset,
                       MaterialPointResult<T>& out) {
  const int c = 0;  // tensile: the control component is eps_ll
  auto run_to = [&](double x, PointState<T>* s_out) -> std::optional<T> {
    drv.set_state(before);
    if (!drv.advance(x).ok) return std::nullopt;
    *s_out = drv.state();
    return axial_plastic_strain(drv, *s_out) - offset;
  };
  PointState<T> s_root = drv.state();
  T g_root = axial_plastic_strain(drv, s_root) - offset;
  double x0 = 0.0, g0 = value_of(axial_plastic_strain(drv, before)) - offset;
  double x1 = d, g1 = value_of(g_root), x_root = d;
  constexpr double tol = 1e-14;
  int same_side = 0;
  for (int it = 0; it < 100 && std::abs(g1) > tol; ++it) {
    double x = x1 - g1 * (x1 - x0) / (g1 - g0);
    if (!(x > std::min(x0, x1) && x < std::max(x0, x1))) x = 0.5 * (x0 + x1);
    PointState<T> s;
    const auto g = run_to(x, &s);
    if (!g) break;
    const double gv = value_of(*g);
    s_root = s; g_root = *g; x_root = x;
    if (gv * g1 < 0.0) { x0 = x1; g0 = g1; same_side = 0; }
    else if (++same_side > 1) { g0 *= 0.5; }
    x1 = x; g1 = gv;
  }
  T sk = drv.stress_loading(s_root.material)(c);
  T sc = sk / drv.jacobian(s_root);
  if constexpr (!std::is_same_v<T, double>) {
    const double h = 1e-7 * std::max(1e-3, std::abs(d));
    PointState<T> sh;
    if (const auto gh = run_to(x_root + h, &sh)) {
      const double dgdx = (value_of(*gh) - value_of(g_root)) / h;
      const T skh = drv.stress_loading(sh.material)(c);
      const double dkdx = (value_of(skh) - value_of(sk)) / h;
      const double dcdx = (value_of(skh / drv.jacobian(sh)) - value_of(sc)) / h;
      const T dg = g_root - T(value_of(g_root));  // zero value, derivative d g / d p
      if (dgdx != 0.0) {
        sk = sk - (dkdx / dgdx) * dg;
        sc = sc - (dcdx / dgdx) * dg;
      }
    }
  }
  out.offset_yield_stress_kirchhoff = sk;
  out.offset_yield_stress = sc;
  out.offset_yield_strain = s_root.control_strain;
}

// One point of the curve at the driver's current state.
template <typename T>
CurvePoint<T> curve_point(const MaterialPointDriver<T>& drv, int c, int inc, int seg, double cumulative) {
  const auto& s = drv.state();
  CurvePoint<T> p;
  p.increment = inc;
  p.segment = seg;
  p.control_strain = s.control_strain;
  p.cumulative_strain = cumulative;
  const T J = drv.jacobian(s);
  p.stress_kirchhoff = drv.stress_loading(s.material)(c);
  p.stress = p.stress_kirchhoff / J;
  p.strain_loading = s.strain;
  p.thickness_strain = drv.thickness_strain(s);
  p.stress_material = s.material.stress / J;
  p.plastic_strain = s.material.plastic_strain;
  const T xzz = s.material.back_stress_zz;
  p.back_stress << s.material.back_stress(0) + xzz, s.material.back_stress(1) + xzz, xzz, s.material.back_stress(2);
  p.eqps = s.material.eqps;
  return p;
}

// The r-value at the control strain r_strain, reached by a side run from `before` (the state at
// the start of the increment that crosses it): the ratio of the width to the thickness
// components of the flow direction. The driver is put back as it was.
template <typename T>
void measure_r_value(MaterialPointDriver<T>& drv, const material::ReturnMapping<T, 3>& law, const PointState<T>& before, double r_strain,
                     MaterialPointResult<T>& out) {
  const auto events_before = drv.yield_events();
  const auto counters_before = drv.counters();
  DriverStatus st = drv.advance(r_strain - before.control_strain);
  if (st.ok && value_of(drv.state().material.eqps) > 0.0) {
    const auto n_m = law.flow_direction(drv.state().material);
    const auto n_l = drv.to_loading_strain(n_m);
    const T n_zz = -(n_m(0) + n_m(1));
    out.r_value = n_l(1) / n_zz;
  }
  drv.set_state(before);
  drv.set_yield_events(events_before);
  drv.set_counters(counters_before);
}

// The 0.2 %-offset yield stress inside the increment from `before` of size d (find_offset_yield);
// the driver is put back at the increment's end, the side runs not counted as work of the curve.
template <typename T>
void measure_offset_yield(MaterialPointDriver<T>& drv, const PointState<T>& before, double d, double offset, MaterialPointResult<T>& out) {
  const PointState<T> after = drv.state();
  const auto events_after = drv.yield_events();
  const auto counters_after = drv.counters();
  find_offset_yield(drv, before, d, offset, out);
  drv.set_state(after);
  drv.set_yield_events(events_after);
  drv.set_counters(counters_after);
}

template <typename T>
MaterialPointResult<T> run_material_point(const material::MaterialParams<T>& params, const MaterialPointSetup& setup) {
  check_setup(setup);
  MaterialPointResult<T> out;
  const material::ReturnMapping<T, 3> law(params, setup.driver.return_mapping);
  MaterialPointDriver<T> drv(law, loading_control(setup), setup.driver);
  const int c = loading_control(setup).control;
  const bool tensile = setup.kind == MaterialPointKind::tensile;

  // Increments per segment, proportional to its length.
  double total = 0.0, prev = 0.0;
  for (double t : setup.strain_path) { total += std::abs(t - prev); prev = t; }
  out.curve.push_back(curve_point(drv, c, 0, 0, 0.0));
  int inc = 0;
  double cumulative = 0.0;
  prev = 0.0;
  double prev_dir = 0.0;
  bool reversed = false;  // r-value and offset yield belong to the first monotonic stretch
  for (std::size_t seg = 0; seg < setup.strain_path.size(); ++seg) {
    const double target = setup.strain_path[seg];
    const double len = std::abs(target - prev);
    const double dir = target > prev ? 1.0 : -1.0;
    const int n = std::max(1, static_cast<int>(std::lround(setup.increments * len / total)));
    drv.set_segment(static_cast<int>(seg));
    if (prev_dir != 0.0 && dir != prev_dir) {
      reversed = true;
      auto s = drv.state();
      s.plastic = false;  // a reversal starts elastic: look for the reverse yield onset
      drv.set_state(s);
    }
    double last_goal = prev;
    for (int k = 1; k <= n; ++k) {
      const double goal = k == n ? target : prev + (target - prev) * static_cast<double>(k) / n;
      const PointState<T> before = drv.state();
      const double d = goal - before.control_strain;
      const bool first_stretch = tensile && !reversed;
      // r-value at an exact strain (tensile, first monotonic stretch); the crossing is tested
      // on the grid of increment goals, so a strain on a boundary is found once.
      if (first_stretch && setup.want_r_value && !out.r_value && (last_goal - setup.r_value_strain) * (goal - setup.r_value_strain) <= 0.0 &&
          goal != last_goal)
        measure_r_value(drv, law, before, setup.r_value_strain, out);
      last_goal = goal;
      DriverStatus st = drv.advance(d);
      if (!st.ok) {
        out.ok = false;
        out.message = st.message;
        break;
      }
      ++inc;
      cumulative += std::abs(d);
      // 0.2 %-offset yield stress: root of eps_p_ll(x) = offset inside this increment.
      if (first_stretch && setup.want_offset_yield && !out.offset_yield_stress &&
          value_of(axial_plastic_strain(drv, drv.state())) >= setup.offset_strain)
        measure_offset_yield(drv, before, d, setup.offset_strain, out);
      out.curve.push_back(curve_point(drv, c, inc, static_cast<int>(seg), cumulative));
    }
    if (!out.ok) break;
    prev = target;
    prev_dir = dir;
  }
  out.yield_events = drv.yield_events();
  const auto& counters = drv.counters();
  out.substeps = counters.substeps;
  out.cutbacks = counters.cutbacks;
  out.newton_iterations = counters.newton_iterations;
  out.accuracy_limited_substeps = counters.accuracy_limited;
  return out;
}

}  // namespace spifit::scene
