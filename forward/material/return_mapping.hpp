#pragma once
// Implicit return mapping for Hill48 + an isotropic hardening law (hardening/hardening_laws.hpp)
// + none or a kinematic hardening law (kinematic/kinematic_laws.hpp: Armstrong-Frederick,
// Ziegler), in 3D (Dim = 6) or plane stress (Dim = 3), with the consistent tangent.
//
// Algorithm (docs/design/numerics-material.md gives the derivation):
//  * Elastic predictor sigma_tr = sigma_0 + C d_eps; xi = sigma - X is the shifted stress.
//  * Plastic corrector, closest-point projection: d_eps_p = dl * P xi / (2 sigma_F) and
//    sigma = sigma_tr - C d_eps_p, with dl the equivalent plastic strain increment.
//  * The back-stress ODE is integrated exponentially over the step with the end-of-step flow
//    direction (exact for proportional loading, e.g. von Mises uniaxial AF and Ziegler):
//      AF:      X1 = m X0 + k psi(CX dl) A d_eps_p,    m = exp(-CX dl), k = CX Xsat
//      Ziegler: X1 = m X0 + psi(GA dl) dl CA xi / sigma_F,  m = exp(-GA dl)
//    with psi(x) = (1 - e^-x)/x. psi -> 1 recovers backward Euler at small steps.
//  * For a given dl, xi solves the linear system  Mat(dl) xi = b(dl) with
//      Mat = a I + q (C + e A) P,  q = dl / (2 sigma_F(p0 + dl)),  b = sigma_tr - m X0,
//    (a, e, m) depending on the law. The scalar consistency condition
//      phi(dl) = sigma_eq(xi(dl)) - sigma_F(p0 + dl) = 0
//    is solved by Newton's method safeguarded by bisection on a bracket, so that large
//    increments (10 % strain and more) converge.
//  * The consistent tangent follows from implicit differentiation of (xi, dl).
// A registered yield function (yield/yield_functions.hpp: Yld2000-2d, plane stress only) has no
// such linear system: for a given dl, xi solves the nonlinear a xi + dl (C + e A) w n(xi) = b, with
// n = d sigma_eq / d xi and the weight w = (sigma_eq / sigma_F)^(k - 1) (1 at the root), by
// Newton's method with a line search on the smooth convex potential whose gradient it is
// (evaluate_general); the scalar loop on dl and the tangent keep their form.
// With T = ceres::Jet the multiplier is converged in double precision on a value copy of the
// law and one Newton update in Jets follows: exact parameter derivatives (integrate_jet).
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/material/material_params.hpp"
#include "forward/material/material_state.hpp"
#include "forward/material/scalar.hpp"
#include "forward/material/stress_space.hpp"
#include "forward/material/yield/yield_functions.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <type_traits>

namespace spifit::material {

struct ReturnMappingOptions {
  double tolerance = 1e-13;  // |phi| <= tolerance * sigma_F
  int max_iterations = 80;
  // Jets without a tangent (direct differentiation of FE runs): the implicit derivatives from one
  // Jet evaluation at the converged multiplier, moved to first order along d/d dl, instead of a
  // Newton step and a second evaluation. The derivatives agree to the multiplier's residual.
  bool single_jet_evaluation = false;
};

template <typename T, int Dim>
class ReturnMapping {
 public:
  using Space = StressSpace<T, Dim>;
  using Vec = typename Space::Vec;
  using Mat = typename Space::Mat;
  using State = MaterialState<T, Dim>;

  explicit ReturnMapping(const MaterialParams<T>& params, ReturnMappingOptions options = {})
      : m_(params), options_(options), C_(Space::elastic(params)), P_(Space::hill(params)),
        A_(Space::kinematic_map()), CP_(C_ * P_), general_(params.yield.active()) {
    if (general_ && Dim != 3)
      throw std::invalid_argument(yield_function_title(params.yield.law) + " is a plane-stress yield function: it has no 3D return mapping");
    if constexpr (!std::is_same_v<T, double>) values_ = std::make_shared<const ReturnMapping<double, Dim>>(values_of(params), options);
  }

  const MaterialParams<T>& params() const { return m_; }
  // Jets: the same law on the parameter values (double precision iterations).
  const ReturnMapping<double, Dim>& value_law() const {
    if constexpr (std::is_same_v<T, double>) return *this;
    else return *values_;
  }
  const Mat& elastic_matrix() const { return C_; }
  const Mat& hill_matrix() const { return P_; }
  // Hill 1948: sigma_eq^2 = xi^T P xi / 2 (hill_matrix); otherwise a registered function.
  bool quadratic() const { return !general_; }

  T equivalent_stress(const Vec& xi) const {
    using std::sqrt;
    if constexpr (Dim == 3) {
      if (general_) return general_value(xi, false).value;
    }
    const T q = 0.5 * xi.dot(P_ * xi);
    return value_of(q) > 0.0 ? sqrt(q) : T(0.0);
  }
  T yield_stress(const T& p) const { return hardening_stress(m_, p); }
  // Yield stress at the state's eqps: the kept value when there is one (MaterialState::flow_stress).
  T flow_stress(const State& s) const { return value_of(s.flow_stress) >= 0.0 ? s.flow_stress : yield_stress(s.eqps); }
  T yield_function(const State& s) const {
    return equivalent_stress(s.stress - s.back_stress) - flow_stress(s);
  }
  // d sigma_eq / d sigma at the shifted stress: the plastic strain rate (engineering shear)
  // per unit equivalent plastic strain rate.
  Vec flow_direction(const State& s) const { return flow_direction_at(Vec(s.stress - s.back_stress)); }
  // The same at a shifted stress xi.
  Vec flow_direction_at(const Vec& xi) const {
    if constexpr (Dim == 3) {
      if (general_) return general_value(xi, false).gradient;
    }
    const T seq = equivalent_stress(xi);
    return value_of(seq) > 0.0 ? Vec(P_ * xi / (2.0 * seq)) : Vec(Vec::Zero());
  }
  // Rate of the back-stress decay per unit plastic strain; the scenes bound rate * dl per
  // sub-step for accuracy (0 for isotropic hardening, where the update is exact for
  // proportional loading).
  double kinematic_rate(const State& s) const {
    if (!m_.kinematic.active()) return 0.0;
    return visit_kinematic_law(m_.kinematic.law, [&](auto law) { return decltype(law)::rate(m_.kinematic.c.data(), flow_stress(s)); });
  }

  // Integrates from the committed state s0 over the strain increment d_eps (engineering
  // shear) into s1; fills the consistent tangent d sigma_1 / d eps if requested.
  UpdateResult integrate(const State& s0, const Vec& d_eps, State& s1, Mat* tangent) const {
    UpdateResult result;
    s1 = s0;
    const Vec sigma_tr = s0.stress + C_ * d_eps;
    s1.stress = sigma_tr;
    for (int i = 0; i < Dim; ++i) {
      if (!is_finite(sigma_tr(i))) return fail(result, "non-finite trial stress (strain increment or state is NaN/inf)");
    }
    if (!m_.plastic) {
      if (tangent) *tangent = C_;
      return result;
    }
    const T s_ref = flow_stress(s0);
    s1.flow_stress = s_ref;  // the state's yield stress if the step is elastic; assemble() sets it otherwise
    const T f_tr = equivalent_stress(sigma_tr - s0.back_stress) - s_ref;
    if (!is_finite(f_tr)) return fail(result, "non-finite trial stress");
    if (value_of(f_tr) <= options_.tolerance * value_of(s_ref)) {
      if (tangent) *tangent = C_;
      return result;
    }
    result.plastic = true;
    if constexpr (!std::is_same_v<T, double>) return integrate_jet(s0, d_eps, sigma_tr, s1, tangent, result);

    // Convergence floor: the trial deviator is only known to about eps_mach * |sigma_tr|
    // (a large pressure), so |phi| cannot go below that.
    const double phi_tol = std::max(options_.tolerance * value_of(s_ref),
                                    64.0 * std::numeric_limits<double>::epsilon() * value_of(sigma_tr.cwiseAbs().maxCoeff()));
    Eval ev;
    T dl = T(0.0);
    evaluate(s0, sigma_tr, dl, ev);
    double lo = 0.0, hi = std::numeric_limits<double>::infinity();
    bool converged = false;
    for (int it = 0; it < options_.max_iterations; ++it) {
      result.iterations = it + 1;
      const double phi = value_of(ev.phi);
      const double dl_v = value_of(dl);
      if (ev.valid) {
        if (phi > 0.0) lo = std::max(lo, dl_v); else hi = std::min(hi, dl_v);
      } else {
        hi = std::min(hi, dl_v);
      }
      if (ev.valid && std::abs(phi) <= std::max(phi_tol, options_.tolerance * value_of(ev.s)) && it > 0) {
        converged = true;
        break;
      }
      if (hi - lo <= 1e-15 * std::max(1.0, hi) && std::isfinite(hi)) {
        converged = ev.valid;
        break;
      }
      // Newton on r(dl) = sigma_F / sigma_eq - 1, which has the same root as phi but is
      // nearly linear in dl (exactly so for von Mises without hardening), so large steps
      // converge in a few iterations; phi's sign keeps the bracket.
      const double seq = ev.valid ? value_of(ev.seq) : 0.0;
      const double dseq = ev.valid ? value_of(ev.dphi + ev.ds) : 0.0;
      const double r = ev.valid ? value_of(ev.s) / seq - 1.0 : 0.0;
      const double dr = ev.valid ? (value_of(ev.ds) * seq - value_of(ev.s) * dseq) / (seq * seq) : 0.0;
      const double cand = dr > 0.0 ? dl_v - r / dr : -1.0;
      // A registered function's weighted iteration (evaluate_general) makes xi(dl) steep at the
      // trial state (w = (sigma_eq / sigma_F)^(k - 1) far off the surface): its first step is the
      // closest-point estimate phi_tr / (n . C n + d sigma_F / dp) instead, and Newton goes on
      // from there.
      const double first = general_ && it == 0 && ev.valid ? value_of(ev.phi / (ev.grad.dot(C_ * ev.grad) + ev.ds)) : -1.0;
      if (first > lo && first < hi && std::isfinite(first)) {
        dl = T(first);
      } else if (dr > 0.0 && cand > lo && cand < hi && std::isfinite(cand)) {
        const T rT = ev.s / ev.seq - 1.0;
        const T drT = (ev.ds * ev.seq - ev.s * (ev.dphi + ev.ds)) / (ev.seq * ev.seq);
        dl = dl - rT / drT;  // carried out in T (Jet derivatives)
      } else if (std::isfinite(hi)) {
        dl = T(0.5 * (lo + hi));
      } else {
        dl = T(std::max(4.0 * dl_v, 1e-6));
      }
      evaluate(s0, sigma_tr, dl, ev);
    }
    if (!converged) return fail(result, "return mapping did not converge");
    if (!ev.valid) return fail(result, "return mapping ended in an invalid state");

    return assemble(s0, sigma_tr, dl, ev, s1, tangent, result);
  }

 private:
  struct Eval {
    T s, ds, q, dq;
    KinematicStep<T> k;  // the kinematic law's a, e, m and their derivatives
    Vec xi, dxi;
    T seq, phi, dphi;
    Mat Minv;  // inverse of Mat(dl): closed-form cofactors for 3x3, LU for 6x6
    // Registered yield function: d sigma_eq / d xi, the weighted flow w n, d (dl w n) / d dl and
    // d (w n) / d xi at xi (evaluate_general).
    // Set (zero) even where unused, so that copies of an evaluation read no indeterminate values.
    Vec grad = Vec::Zero(), wn = Vec::Zero(), n = Vec::Zero();
    Mat hess;
    T dl;  // the multiplier of this evaluation
    bool valid = false;
  };

  // Plane stress only (the constructor refuses a registered function in 3D).
  YieldValue<T> general_value(const Eigen::Matrix<T, 3, 1>& xi, bool hessian) const {
    YieldValue<T> v;
    registered_yield_value(m_, xi, v, hessian);
    return v;
  }

  // End-of-step state (and tangent) from the converged evaluation.
  UpdateResult assemble(const State& s0, const Vec& sigma_tr, const T& dl, const Eval& ev, State& s1, Mat* tangent,
                        UpdateResult result) const {
    const Vec d_eps_p = general_ ? Vec(dl * ev.wn) : Vec(ev.q * (P_ * ev.xi));
    s1.stress = sigma_tr - C_ * d_eps_p;
    if (m_.kinematic.active()) s1.back_stress = s1.stress - ev.xi;  // else X1 = X0 exactly
    s1.plastic_strain = s0.plastic_strain + d_eps_p;
    s1.eqps = s0.eqps + dl;
    s1.flow_stress = ev.s;  // yield_stress(s0.eqps + dl) of the last evaluation: that of s1.eqps
    s1.plastic_work = s0.plastic_work + s1.stress.dot(d_eps_p);
    if constexpr (Dim == 3) {
      if (m_.kinematic.active()) {
        const T d_eps_p_zz = -(d_eps_p(0) + d_eps_p(1));
        s1.back_stress_zz = visit_kinematic_law(m_.kinematic.law, [&](auto law) {
          return decltype(law)::back_stress_zz(m_.kinematic.c.data(), ev.k, s0.back_stress_zz, d_eps_p_zz);
        });
      }
    }
    for (int i = 0; i < Dim; ++i) {
      if (!is_finite(s1.stress(i)) || !is_finite(s1.back_stress(i))) {
        return fail(result, "non-finite stress after return mapping");
      }
    }
    if (tangent && general_) {
      const Vec g = -(ev.Minv.transpose() * ev.grad) / ev.dphi;  // d dl / d sigma_tr
      const Mat dxi = ev.Minv + ev.dxi * g.transpose();
      const Mat dsig_dtr = Mat::Identity() - C_ * (ev.n * g.transpose() + dl * ev.hess * dxi);
      *tangent = dsig_dtr * C_;
    } else if (tangent) {
      const Mat& Minv = ev.Minv;
      const Vec grad = P_ * ev.xi / (2.0 * ev.seq);
      const Vec phi_tr = Minv.transpose() * grad;
      const Vec g = -phi_tr / ev.dphi;  // d dl / d sigma_tr
      const Mat dxi = Minv + ev.dxi * g.transpose();
      const Mat& CP = CP_;
      const Mat dsig_dtr = Mat::Identity() - ev.q * CP * dxi - (CP * ev.xi) * (ev.dq * g.transpose());
      *tangent = dsig_dtr * C_;
    }
    return result;
  }

  // Jets: converge in double precision on the value law, then one Newton step in Jets from
  // the converged multiplier. At a root the Newton map's derivative is the implicit
  // derivative -phi_p / phi', whatever the starting derivative: exact, at two Jet evaluations
  // instead of one per iteration.
  UpdateResult integrate_jet(const State& s0, const Vec& d_eps, const Vec& sigma_tr, State& s1, Mat* tangent,
                             UpdateResult result) const {
    MaterialState<double, Dim> v0 = values_of(s0), v1;
    Eigen::Matrix<double, Dim, 1> dv;
    for (int i = 0; i < Dim; ++i) dv(i) = value_of(d_eps(i));
    const UpdateResult rv = values_->integrate(v0, dv, v1, nullptr);
    if (!rv.ok()) return fail(result, rv.reason);
    result.iterations = rv.iterations;
    if (!rv.plastic) {  // the value law found the step elastic after all
      result.plastic = false;
      if (tangent) *tangent = C_;
      return result;
    }
    Eval ev;
    T dl = T(v1.eqps - v0.eqps);
    evaluate(s0, sigma_tr, dl, ev);
    if (!ev.valid) return fail(result, "invalid state at the converged plastic multiplier");
    if (options_.single_jet_evaluation && !general_ && !tangent) {
      // Every quantity assemble() reads, moved by delta along its derivative in dl: delta's value
      // is the multiplier's residual (round-off), its derivatives the implicit ones.
      const T delta = -ev.phi / ev.dphi;
      dl = dl + delta;
      ev.xi = ev.xi + ev.dxi * delta;
      ev.s = ev.s + ev.ds * delta;
      ev.q = ev.q + ev.dq * delta;
      ev.k.a = ev.k.a + ev.k.da * delta;
      ev.k.e = ev.k.e + ev.k.de * delta;
      ev.k.m = ev.k.m + ev.k.dm * delta;
      return assemble(s0, sigma_tr, dl, ev, s1, tangent, result);
    }
    dl = dl - ev.phi / ev.dphi;
    evaluate(s0, sigma_tr, dl, ev);
    if (!ev.valid) return fail(result, "invalid state at the converged plastic multiplier");
    return assemble(s0, sigma_tr, dl, ev, s1, tangent, result);
  }


  static UpdateResult fail(UpdateResult r, const char* why) {
    r.status = UpdateStatus::failed;
    r.suggested_scale = 0.5;
    r.reason = why;
    return r;
  }

  // The hardening and kinematic laws at dl: sigma_F, its slope, q = dl / (2 sigma_F) and the
  // kinematic step's a, e, m.
  void laws_at(const State& s0, const T& dl, Eval& ev) const {
    ev.s = yield_stress(s0.eqps + dl);
    ev.ds = hardening_slope(m_, s0.eqps, dl, ev.s);
    ev.q = dl / (2.0 * ev.s);
    ev.dq = (ev.s - dl * ev.ds) / (2.0 * ev.s * ev.s);
    ev.k = KinematicStep<T>();
    if (m_.kinematic.active()) {
      visit_kinematic_law(m_.kinematic.law, [&](auto law) {
        decltype(law)::step(m_.kinematic.c.data(), dl, ev.s, ev.ds, ev.k);
        return 0;
      });
    }
  }

  // xi(dl), phi(dl) and d phi / d dl for the current law (see the header comment).
  void evaluate(const State& s0, const Vec& sigma_tr, const T& dl, Eval& ev) const {
    if constexpr (Dim == 3) {
      if (general_) return evaluate_general(s0, sigma_tr, dl, ev);
    }
    // The slope may reuse the stress (Swift: n sigma_F / (eps0 + p), one pow per evaluation).
    laws_at(s0, dl, ev);
    const T &a = ev.k.a, &da = ev.k.da, &e = ev.k.e, &de = ev.k.de, &m = ev.k.m, &dm = ev.k.dm;
    // Isotropic hardening (a = 1, e = 0): the products are constants of the law.
    const bool isotropic = !m_.kinematic.active();
    const Mat KP = isotropic ? CP_ : Mat((C_ + e * A_) * P_);
    const Mat M = a * Mat::Identity() + ev.q * KP;
    const Mat dM = isotropic ? Mat(ev.dq * KP) : Mat(da * Mat::Identity() + ev.dq * KP + (ev.q * de) * (A_ * P_));
    const Vec b = sigma_tr - m * s0.back_stress;
    const Vec db = -dm * s0.back_stress;
    if constexpr (Dim <= 4) {
      ev.Minv = M.inverse();
    } else {
      // The elastic matrix, Hill's matrix (material frame) and the kinematic map leave the
      // normal and the shear components uncoupled: M is a 3 x 3 block and a diagonal.
      ev.Minv.setZero();
      ev.Minv.template topLeftCorner<3, 3>() = M.template topLeftCorner<3, 3>().inverse();
      for (int i = 3; i < Dim; ++i) ev.Minv(i, i) = 1.0 / M(i, i);
    }
    if constexpr (Dim == 6) {
      // P h = 0 for the hydrostatic direction h, so M h = a h: solve the deviatoric part
      // only and add the hydrostatic part exactly (a large pressure would otherwise swamp
      // the deviatoric digits that decide yielding).
      const T bh = (b(0) + b(1) + b(2)) / 3.0;
      const T dbh = (db(0) + db(1) + db(2)) / 3.0;
      Vec bd = b, dbd = db;
      for (int i = 0; i < 3; ++i) { bd(i) -= bh; dbd(i) -= dbh; }
      const Vec xid = ev.Minv * bd;
      ev.xi = xid;
      for (int i = 0; i < 3; ++i) ev.xi(i) += bh / a;
      // d xi / d dl: deviatoric part from the solve, hydrostatic part d(bh / a).
      ev.dxi = ev.Minv * (dbd - dM * xid);
      for (int i = 0; i < 3; ++i) ev.dxi(i) += dbh / a - bh * da / (a * a);
    } else {
      ev.xi = ev.Minv * b;
      ev.dxi = ev.Minv * (db - dM * ev.xi);
    }
    ev.seq = equivalent_stress(ev.xi);
    ev.phi = ev.seq - ev.s;
    ev.valid = is_finite(ev.phi) && value_of(ev.seq) > 0.0 && is_finite(ev.Minv(0, 0));
    if (ev.valid) {
      const Vec grad = P_ * ev.xi / (2.0 * ev.seq);
      ev.dphi = grad.dot(ev.dxi) - ev.ds;
      ev.valid = is_finite(ev.dphi);
    }
  }

  // The same for a registered yield function: xi(dl) solves
  //   R(xi) = a xi + dl K w(xi) n(xi) - b = 0,  K = C + e A,  w = (sigma_eq / sigma_F)^(k - 1),
  // with k the function's exponent (sigma_eq^k is smooth). At the root sigma_eq = sigma_F, so
  // w = 1 and the plastic strain is dl n; away from it the weight makes R the gradient (times K)
  // of the smooth, strictly convex psi(xi) = a xi^T K^-1 xi / 2 + dl sigma_F (sigma_eq /
  // sigma_F)^k / k - xi^T K^-1 b: for Hill (k = 2) R is the linear system above, and Newton's
  // method with a backtracking line search on psi converges for any dl, from the previous
  // evaluation's xi. The iteration on sigma_eq itself (w = 1) has a cone at xi = 0 that large
  // increments reach, where Newton stalls.
  void evaluate_general(const State& s0, const Vec& sigma_tr, const T& dl, Eval& ev) const requires(Dim == 3) {
    const bool warm = ev.valid;
    ev.valid = false;
    laws_at(s0, dl, ev);
    const T &a = ev.k.a, &da = ev.k.da, &e = ev.k.e, &de = ev.k.de, &m = ev.k.m, &dm = ev.k.dm;
    const bool isotropic = !m_.kinematic.active();
    const Mat K = isotropic ? C_ : Mat(C_ + e * A_);
    const Mat Kinv = K.inverse();
    const Vec b = sigma_tr - m * s0.back_stress;
    const Vec db = -dm * s0.back_stress;
    const Vec Kb = Kinv * b;
    const T& sF = ev.s;
    // The weighted gradient w n and its Jacobian G = w H + (k - 1) (w / sigma_eq) n n^T.
    struct Weighted {
      YieldValue<T> y;
      T w;
      Vec wn;
      Mat G;
    };
    auto weighted = [&](const Vec& x, Weighted& out) {
      out.y = general_value(x, true);
      if (!(value_of(out.y.value) > 0.0)) return false;
      const T& k = out.y.exponent;
      out.w = real_power(T(out.y.value / sF), T(k - 1.0));
      out.wn = out.w * out.y.gradient;
      out.G = out.w * out.y.hessian + ((k - 1.0) * out.w / out.y.value) * (out.y.gradient * out.y.gradient.transpose());
      return is_finite(out.w);
    };
    auto psi = [&](const Vec& x, const Weighted& wv) {
      const T& k = wv.y.exponent;
      return value_of(0.5 * a * x.dot(Kinv * x) + dl * sF * wv.w * (wv.y.value / sF) / k - x.dot(Kb));
    };

    // From the previous evaluation's xi moved along its d xi / d dl (error second order in the
    // change of dl; not from the trial state, where xi(dl) is steep).
    // From the trial state, the first step of a closest-point iteration (xi_tr - dl K n_tr).
    Vec xi = !warm ? Vec(b / a) : value_of(ev.dl) > 0.0 ? Vec(ev.xi + ev.dxi * (dl - ev.dl)) : Vec(ev.xi - dl * (K * ev.grad));
    Weighted cur;
    if (!weighted(xi, cur)) {
      xi = b / a;
      if (!weighted(xi, cur)) return;
    }
    const int extra_steps = std::is_same_v<T, double> ? 0 : 1;  // Jets: one step past convergence
    int after = -1;
    for (int it = 0; it < 100 && after < extra_steps; ++it) {
      const Vec R = a * xi + dl * (K * cur.wn) - b;
      const Mat J = a * Mat::Identity() + dl * (K * cur.G);
      const Vec d = -(J.inverse() * R);
      const double size = value_of(d.cwiseAbs().maxCoeff()), ref = value_of(xi.cwiseAbs().maxCoeff());
      if (!std::isfinite(size)) return;
      if (after >= 0) {  // Jets: the full step at the root carries the implicit derivatives
        xi = xi + d;
        if (!weighted(xi, cur)) return;
        ++after;
        continue;
      }
      double t = 1.0;
      Vec trial = xi + d;
      Weighted next;
      bool ok = weighted(trial, next);
      if (size > 1e-8 * ref) {  // far from the root: backtrack on psi
        const double psi0 = psi(xi, cur);
        const double slope = value_of((Kinv * R).dot(d));
        while (t > 1e-12 && !(ok && psi(trial, next) <= psi0 + 1e-4 * t * slope)) {
          t *= 0.5;
          trial = xi + t * d;
          ok = weighted(trial, next);
        }
      }
      if (!ok) return;
      xi = trial;
      cur = next;
      // Newton converges quadratically here: after a full step of 1e-8 the error is of round-off.
      if (t == 1.0 && size <= 1e-8 * ref) after = 0;
    }
    if (after < 0) return;  // the inner iteration did not converge: the outer loop bisects
    const T& k = cur.y.exponent;
    const Mat J = a * Mat::Identity() + dl * (K * cur.G);
    ev.Minv = J.inverse();
    // d R / d dl, with d w / d dl = -(k - 1) w ds / sigma_F.
    const Vec dwn = (-(k - 1.0) * ev.ds / sF) * cur.wn;
    ev.n = cur.wn + dl * dwn;  // d (dl w n) / d dl at fixed xi
    const Vec dR = da * xi + K * ev.n + (dl * de) * (A_ * cur.wn) - db;
    ev.xi = xi;
    ev.dl = dl;
    ev.dxi = -(ev.Minv * dR);
    ev.wn = cur.wn;
    ev.grad = cur.y.gradient;
    ev.hess = cur.G;
    ev.seq = cur.y.value;
    ev.phi = ev.seq - ev.s;
    ev.dphi = ev.grad.dot(ev.dxi) - ev.ds;
    ev.valid = is_finite(ev.phi) && is_finite(ev.dphi) && is_finite(ev.Minv(0, 0));
  }

  MaterialParams<T> m_;
  std::shared_ptr<const ReturnMapping<double, Dim>> values_;  // Jets only: the value law
  ReturnMappingOptions options_;
  Mat C_, P_, A_;
  Mat CP_;  // C P
  bool general_ = false;  // a registered yield function (yield_functions.hpp), not Hill 1948
};

}  // namespace spifit::material
