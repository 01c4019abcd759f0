#pragma once
// Strain-controlled driver of one plane-stress material point under mixed control: the
// control strain is prescribed, some components are held at zero strain, the others follow
// a stress condition sigma_i = ratio_i * sigma_control, solved by Newton's method with the
// consistent tangent. Increments are sub-divided automatically when the constitutive update
// or the Newton loop fails (cut back by the update's suggested factor) and when the back-stress
// would move too far in one step (accuracy of the kinematic integration).
#include "forward/material/return_mapping.hpp"
#include "forward/scenes/material_point/loading_frame.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace spifit::scene {

struct DriverOptions {
  double tolerance = 1e-12;          // stress residual / max(|sigma|, sigma_F0)
  int max_newton_iterations = 30;
  int max_cutbacks = 20;             // halvings of one increment before giving up
  double kinematic_substep = 0.05;   // bound on (back-stress decay rate) * d eps_p per sub-step
  int max_substeps = 2000;           // per call of advance(); beyond it the accuracy bound is waived
  material::ReturnMappingOptions return_mapping;
};

template <typename T>
struct YieldEvent {
  int segment = 0;
  double control_strain = 0.0;  // value of the control strain where yielding starts
  T stress_kirchhoff{};         // control stress component at the onset
  T stress{};                   // the same as true (Cauchy) stress
};

template <typename T>
struct PointState {
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  Vec3 strain = Vec3::Zero();  // total strain in the loading frame (eps_ll, eps_ww, gamma_lw)
  material::MaterialState<T, 3> material;  // material frame
  double control_strain = 0.0;
  double ratio[3] = {0.0, 0.0, 0.0};  // last d eps_i / d control, a Newton start
  bool plastic = false;               // last committed step was plastic
  double substep_hint = 0.0;          // next sub-step size (0: whole increment)
};

struct DriverCounters {
  int substeps = 0, cutbacks = 0, newton_iterations = 0;
  int accuracy_limited = 0;  // sub-steps accepted beyond the kinematic bound (max_substeps reached)
};

struct DriverStatus {
  bool ok = true;
  std::string message;
};

template <typename T>
class MaterialPointDriver {
 public:
  using Vec3 = Eigen::Matrix<T, 3, 1>;
  using Mat3 = Eigen::Matrix<T, 3, 3>;
  using Law = material::ReturnMapping<T, 3>;
  using MState = material::MaterialState<T, 3>;

  MaterialPointDriver(const Law& law, const LoadingControl& control, DriverOptions options = {})
      : law_(law), control_(control), options_(options) {
    const Eigen::Matrix3d Q = strain_rotation(control.alpha);
    Qd_ = Q;
    Q_ = Q.cast<T>();
    Qinv_ = Q.inverse().cast<T>();
    sigma_ref_ = law.params().plastic ? value_of(law.yield_stress(T(0.0))) : 1e-6 * value_of(law.params().E);
  }

  const PointState<T>& state() const { return state_; }
  void set_state(const PointState<T>& s) { state_ = s; }
  void set_segment(int segment) { segment_ = segment; }
  const std::vector<YieldEvent<T>>& yield_events() const { return events_; }
  void set_yield_events(const std::vector<YieldEvent<T>>& e) { events_ = e; }
  const DriverCounters& counters() const { return counters_; }
  void set_counters(const DriverCounters& c) { counters_ = c; }

  Vec3 stress_loading(const MState& m) const { return Q_.transpose() * m.stress; }
  Vec3 to_loading_strain(const Vec3& e_material) const { return Qinv_ * e_material; }
  const Law& law() const { return law_; }

  // Elastic volume ratio J = exp(tr eps_e); the Cauchy stress is Kirchhoff / J.
  T jacobian(const PointState<T>& s) const {
    using std::exp;
    const Vec3 ee = Q_ * s.strain - s.material.plastic_strain;
    const T nu = law_.params().nu;
    return exp((1.0 - 2.0 * nu) / (1.0 - nu) * (ee(0) + ee(1)));
  }
  // Total through-thickness log strain (plane stress): elastic + plastic parts.
  T thickness_strain(const PointState<T>& s) const {
    const Vec3 ee = Q_ * s.strain - s.material.plastic_strain;
    const T nu = law_.params().nu;
    return -nu / (1.0 - nu) * (ee(0) + ee(1)) - (s.material.plastic_strain(0) + s.material.plastic_strain(1));
  }

  // Advances the control strain by d, sub-stepping as needed; commits on success.
  // Sub-step sizes: a failed solve is retried with the update's suggested fraction; a step
  // whose back-stress decay rate * d eps_p exceeds options.kinematic_substep is retried with a
  // size predicted from the measured ratio, and the next sub-step starts from that prediction
  // (kept in the state, so re-running from a saved state reproduces the same sub-steps).
  DriverStatus advance(double d) {
    const double target = state_.control_strain + d;  // assigned exactly on the last piece
    double remaining = d;
    int cutbacks = 0, accuracy_retries = 0, pieces = 0;
    while (remaining != 0.0) {
      double size = remaining;
      if (state_.substep_hint > 0.0 && state_.substep_hint < std::abs(remaining)) {
        // Split the rest evenly instead of leaving a sliver at the end of the increment.
        const double n = std::ceil(std::abs(remaining) / state_.substep_hint - 1e-9);
        size = remaining / n;
      }
      Trial trial;
      DriverStatus st = solve(size, trial);
      if (!st.ok) {
        if (++cutbacks > options_.max_cutbacks) {
          st.message = "material point failed at control strain " + format(state_.control_strain) + " (sub-step " +
                       format(size) + ") after " + std::to_string(options_.max_cutbacks) + " cut-backs: " + st.message;
          return st;
        }
        ++counters_.cutbacks;
        state_.substep_hint = std::abs(size) * trial.suggested_scale;
        continue;
      }
      double kappa = 0.0;
      if (options_.kinematic_substep > 0.0) {
        const double dl = value_of(trial.material.eqps - state_.material.eqps);
        kappa = law_.kinematic_rate(trial.material) * dl;
        if (kappa > options_.kinematic_substep) {
          if (pieces < options_.max_substeps && accuracy_retries < 20) {
            ++accuracy_retries;
            state_.substep_hint = std::abs(size) * std::max(0.05, 0.9 * options_.kinematic_substep / kappa);
            continue;
          }
          ++counters_.accuracy_limited;
        }
      }
      const bool last = std::abs(size) >= std::abs(remaining);
      commit(size, trial);
      ++counters_.substeps;
      ++pieces;
      cutbacks = accuracy_retries = 0;
      remaining = last ? 0.0 : remaining - size;
      if (last) state_.control_strain = target;
      // Next sub-step: predicted from this one when the back-stress moved, free otherwise;
      // past max_substeps the rest of the increment goes in one piece.
      state_.substep_hint = (kappa > 0.0 && pieces < options_.max_substeps)
                                ? std::abs(size) * std::min(2.0, 0.9 * options_.kinematic_substep / kappa)
                                : 0.0;
    }
    return {};
  }

 private:
  struct Trial {
    Vec3 d_strain = Vec3::Zero();
    MState material;
    bool plastic = false;
    double suggested_scale = 0.5;
    bool onset = false;
    YieldEvent<T> event;
  };

  // Mixed-control Newton for an increment of size d from s0 with the law `law` (scalar S):
  // returns the converged loading-frame strain increment and end state.
  template <typename S>
  DriverStatus newton(const material::ReturnMapping<S, 3>& law, const material::MaterialState<S, 3>& s0, double d,
                      Eigen::Matrix<S, 3, 1>& de, material::MaterialState<S, 3>& s1, bool* plastic, double* suggested) {
    using V = Eigen::Matrix<S, 3, 1>;
    using M = Eigen::Matrix<S, 3, 3>;
    const int c = control_.control;
    const M Q = Qd_.template cast<S>();
    de = V::Zero();
    for (int i = 0; i < 3; ++i) {
      if (control_.role[i] == ComponentRole::stress_ratio) de(i) = S(state_.ratio[i] * d);
    }
    de(c) = S(d);
    M Dm;
    for (int it = 0; it < options_.max_newton_iterations; ++it) {
      ++counters_.newton_iterations;
      const auto r = law.integrate(s0, V(Q * de), s1, &Dm);
      if (!r.ok()) {
        *suggested = r.suggested_scale;
        return {false, std::string("constitutive update failed: ") + r.reason};
      }
      *plastic = r.plastic;
      V res;
      M J;
      if (!residual(Q, s1.stress, Dm, &res, &J)) return {};  // no stress-controlled component
      const V sL = Q.transpose() * s1.stress;
      const double scale = std::max(sigma_ref_, value_of(sL.cwiseAbs().maxCoeff()));
      if (value_of(res.cwiseAbs().maxCoeff()) <= options_.tolerance * scale) return {};
      const V delta = J.partialPivLu().solve(V(-res));
      for (int i = 0; i < 3; ++i) {
        if (!is_finite(delta(i))) return {false, "singular mixed-control Jacobian"};
        if (control_.role[i] == ComponentRole::stress_ratio) de(i) += delta(i);
      }
    }
    *suggested = 0.5;
    return {false, "mixed-control Newton did not converge"};
  }

  // Residual of the stress conditions and its Jacobian w.r.t. the free strain components
  // (identity rows for the others); false if no component is stress-controlled.
  template <typename S>
  bool residual(const Eigen::Matrix<S, 3, 3>& Q, const Eigen::Matrix<S, 3, 1>& stress_m, const Eigen::Matrix<S, 3, 3>& Dm,
                Eigen::Matrix<S, 3, 1>* res, Eigen::Matrix<S, 3, 3>* J) const {
    const int c = control_.control;
    const Eigen::Matrix<S, 3, 1> sL = Q.transpose() * stress_m;
    const Eigen::Matrix<S, 3, 3> DL = Q.transpose() * Dm * Q;
    *res = Eigen::Matrix<S, 3, 1>::Zero();
    *J = Eigen::Matrix<S, 3, 3>::Identity();
    bool any = false;
    for (int i = 0; i < 3; ++i) {
      if (control_.role[i] != ComponentRole::stress_ratio) continue;
      any = true;
      (*res)(i) = sL(i) - control_.ratio[i] * sL(c);
      for (int j = 0; j < 3; ++j) {
        (*J)(i, j) = control_.role[j] == ComponentRole::stress_ratio ? S(DL(i, j) - control_.ratio[i] * DL(c, j)) : S(i == j ? 1.0 : 0.0);
      }
    }
    return any;
  }

  // One solve of an increment of size d from the committed state (no commit). With Jets the
  // Newton loop runs in double precision on the value law, then one Newton correction in
  // Jets from the converged point gives the exact derivatives (as in the return mapping).
  DriverStatus solve(double d, Trial& trial) {
    if constexpr (std::is_same_v<T, double>) {
      DriverStatus st = newton(law_, state_.material, d, trial.d_strain, trial.material, &trial.plastic, &trial.suggested_scale);
      if (!st.ok) return st;
    } else {
      Eigen::Vector3d dv;
      material::MaterialState<double, 3> v1;
      bool plastic = false;
      DriverStatus st = newton(law_.value_law(), values_of(state_.material), d, dv, v1, &plastic, &trial.suggested_scale);
      if (!st.ok) return st;
      Vec3 de = dv.cast<T>();
      Mat3 Dm;
      for (int pass = 0; pass < 2; ++pass) {
        const auto r = law_.integrate(state_.material, Vec3(Q_ * de), trial.material, &Dm);
        if (!r.ok()) {
          trial.suggested_scale = r.suggested_scale;
          return {false, std::string("constitutive update failed: ") + r.reason};
        }
        trial.plastic = r.plastic;
        Vec3 res;
        Mat3 J;
        if (pass == 1 || !residual(Q_, trial.material.stress, Dm, &res, &J)) break;
        const Vec3 delta = J.partialPivLu().solve(Vec3(-res));
        for (int i = 0; i < 3; ++i) {
          if (control_.role[i] == ComponentRole::stress_ratio) de(i) += delta(i);
        }
      }
      trial.d_strain = de;
    }
    if (trial.plastic && !state_.plastic) detect_onset(d, trial);
    return {};
  }

  // Exact yield onset inside an increment that starts elastic: the elastic response is
  // linear, so the crossing of sigma_eq(xi0 + theta d_sigma) = sigma_F0 is a quadratic in theta.
  void detect_onset(double d, Trial& trial) {
    const int c = control_.control;
    const Mat3 C = law_.elastic_matrix();
    const Mat3 CL = Q_.transpose() * C * Q_;
    Mat3 J = Mat3::Identity();
    Vec3 rhs = Vec3::Zero();
    for (int i = 0; i < 3; ++i) {
      if (control_.role[i] != ComponentRole::stress_ratio) continue;
      for (int j = 0; j < 3; ++j) {
        if (control_.role[j] == ComponentRole::stress_ratio) J(i, j) = CL(i, j) - control_.ratio[i] * CL(c, j);
        else J(i, j) = T(0.0);
      }
      rhs(i) = -(CL(i, c) - control_.ratio[i] * CL(c, c)) * d;
    }
    Vec3 de = J.partialPivLu().solve(rhs);
    de(c) = T(d);
    for (int i = 0; i < 3; ++i) if (control_.role[i] == ComponentRole::zero_strain) de(i) = T(0.0);
    const Vec3 dsig = C * (Q_ * de);
    const Vec3 xi0 = state_.material.stress - state_.material.back_stress;
    const T sF = law_.yield_stress(state_.material.eqps);
    T theta;
    if (law_.quadratic()) {
      const auto& P = law_.hill_matrix();
      const T a = 0.5 * dsig.dot(P * dsig), b = xi0.dot(P * dsig), cc = 0.5 * xi0.dot(P * xi0) - sF * sF;
      using std::sqrt;
      const T disc = b * b - 4.0 * a * cc;
      if (!(value_of(a) > 0.0) || value_of(disc) < 0.0) return;
      theta = (-b + sqrt(disc)) / (2.0 * a);
      // A start state already on (within the return-mapping tolerance outside) the surface
      // yields at the start of the increment.
      if (value_of(theta) < 0.0 && value_of(cc) >= 0.0) theta = T(0.0);
    } else if (!crossing(xi0, dsig, sF, theta)) {
      return;
    }
    if (value_of(theta) < -1e-9 || value_of(theta) > 1.0 + 1e-9) return;
    PointState<T> at = state_;
    at.strain += theta * de;
    at.material.stress += theta * dsig;
    const T sk = stress_loading(at.material)(c);
    trial.onset = true;
    trial.event = {segment_, state_.control_strain + value_of(theta) * d, sk, sk / jacobian(at)};
  }

  // The crossing for any convex yield function: f(theta) = sigma_eq(xi0 + theta d_sigma) - sigma_F0
  // is convex in theta, negative at 0 (else the crossing is at 0) and positive at 1; bisection and
  // Newton in double precision, then one Newton step in T (Jets: the implicit derivative).
  bool crossing(const Vec3& xi0, const Vec3& dsig, const T& sF, T& theta) const {
    auto f = [&](const T& t) { return law_.equivalent_stress(Vec3(xi0 + t * dsig)) - sF; };
    if (value_of(f(T(0.0))) >= 0.0) {
      theta = T(0.0);
      return true;
    }
    if (value_of(f(T(1.0))) < 0.0) return false;
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
      const double mid = 0.5 * (lo + hi);
      (value_of(f(T(mid))) < 0.0 ? lo : hi) = mid;
    }
    theta = T(hi);
    const T slope = law_.flow_direction_at(Vec3(xi0 + theta * dsig)).dot(dsig);
    if (value_of(slope) > 0.0) theta = theta - f(theta) / slope;
    return true;
  }

  void commit(double d, const Trial& trial) {
    if (trial.onset) events_.push_back(trial.event);
    state_.strain += trial.d_strain;
    state_.material = trial.material;
    state_.control_strain += d;
    state_.plastic = trial.plastic;
    if (d != 0.0) {
      for (int i = 0; i < 3; ++i) {
        if (control_.role[i] == ComponentRole::stress_ratio) state_.ratio[i] = value_of(trial.d_strain(i)) / d;
      }
    }
  }

  const Law& law_;
  LoadingControl control_;
  DriverOptions options_;
  Mat3 Q_, Qinv_;
  Eigen::Matrix3d Qd_;  // the rotation is data: double copy for the value iterations
  double sigma_ref_ = 1.0;
  PointState<T> state_;
  std::vector<YieldEvent<T>> events_;
  int segment_ = 0;
  DriverCounters counters_;

  static std::string format(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
  }
};

}  // namespace spifit::scene
