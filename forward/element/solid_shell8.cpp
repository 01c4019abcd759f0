#include "forward/element/solid_shell8.hpp"

#include "forward/io/binary_archive.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace spifit::element {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;
using Row8 = Eigen::Matrix<double, 1, 8>;
using Grad = Eigen::Matrix<double, 3, 8>;  // d e / d x_I per corner (columns)

namespace {

constexpr int kVoigtPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
// The in-plane Gauss points' signs (xi, eta), and the shear sampling points: e13 at
// eta = -1, +1 (xi = 0), e23 at xi = -1, +1 (eta = 0).
constexpr double kColumn[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
constexpr double kShearSample[4][2] = {{0, -1}, {0, 1}, {-1, 0}, {1, 0}};
constexpr int kMaxEnhancedIterations = 12;

// T with E_material = T e for the convective components e (Voigt, engineering shears), where
// E_material = Jinv E_conv Jinv^T and Jinv(c, r) = d xi_r / d X_c.
Voigt6x6 convective_to_material(const Mat3& Jinv) {
  Voigt6x6 T;
  for (int k = 0; k < 6; ++k) {
    Mat3 e = Mat3::Zero();
    const int i = kVoigtPair[k][0], j = kVoigtPair[k][1];
    if (i == j) e(i, i) = 1.0;
    else e(i, j) = e(j, i) = 0.5;
    const Mat3 E = Jinv * e * Jinv.transpose();
    T.col(k) << E(0, 0), E(1, 1), E(2, 2), 2.0 * E(0, 1), 2.0 * E(0, 2), 2.0 * E(1, 2);
  }
  return T;
}

Vec3 tangent(const Eigen::Matrix<double, 3, 8>& x, const Eigen::Matrix<double, 3, 8>& dN, int r) { return x * dN.row(r).transpose(); }

double hex_jacobian_determinant(const Eigen::Matrix<double, 3, 8>& x, const Eigen::Matrix<double, 3, 8>& dN) {
  return tangent(x, dN, 0).cross(tangent(x, dN, 1)).dot(tangent(x, dN, 2));
}

// A sampled convective component: its value, its derivative per corner and the two rows of
// parent derivatives whose symmetric product is its second derivative.
struct Sample {
  double value = 0.0;
  Grad grad;
  Row8 a, b;
};

Sample sample_product(const Eigen::Matrix<double, 3, 8>& x, const Eigen::Matrix<double, 3, 8>& dN, int r, int s, double reference) {
  const Vec3 gr = tangent(x, dN, r), gs = tangent(x, dN, s);
  Sample out;
  out.a = dN.row(r);
  out.b = dN.row(s);
  if (r == s) {
    out.value = 0.5 * gr.dot(gr) - reference;
    out.grad = gr * out.a;
  } else {
    out.value = gr.dot(gs) - reference;
    out.grad = gs * out.a + gr * out.b;
  }
  return out;
}

// The second derivative of a sampled component as an 8 x 8 matrix (times the 3 x 3 identity):
// a a^T for a normal component, a b^T + b a^T for a shear.
Eigen::Matrix<double, 8, 8> second(const Sample& s, bool normal) {
  if (normal) return s.a.transpose() * s.a;
  return s.a.transpose() * s.b + s.b.transpose() * s.a;
}

}  // namespace

struct SolidShell8::Sums {
  HexVector fu = HexVector::Zero();
  EnhancedVector ra = EnhancedVector::Zero();
  Eigen::Matrix<double, kEnhanced, kEnhanced> kaa = Eigen::Matrix<double, kEnhanced, kEnhanced>::Zero();
  Eigen::Matrix<double, 24, kEnhanced> kua = Eigen::Matrix<double, 24, kEnhanced>::Zero();
  // d ra / d x: kua^T where the material tangent is symmetric (filled at the end).
  Eigen::Matrix<double, kEnhanced, 24> kau = Eigen::Matrix<double, kEnhanced, 24>::Zero();
  HexMatrix kuu = HexMatrix::Zero();
};

SolidShell8::SolidShell8(const HexCorners& X, const Eigen::Matrix3d& axes, const Law& law, const ThicknessRule& rule, double enhanced_tolerance)
    : axes_(axes), zeta_(rule.zeta), symmetric_(!law.params().kinematic.active()), enhanced_tolerance_(enhanced_tolerance) {
  if (!(enhanced_tolerance > 0.0)) throw std::invalid_argument("solid-shell: the enhanced strains' tolerance must be > 0, got " + std::to_string(enhanced_tolerance));
  if (!((axes.transpose() * axes - Mat3::Identity()).cwiseAbs().maxCoeff() < 1e-10 && axes.determinant() > 0.0))
    throw std::invalid_argument("material axes of a solid-shell must be orthonormal and right-handed");
  if (rule.zeta.empty()) throw std::invalid_argument("a solid-shell needs at least one point through the thickness");
  HexCorners Xm;
  for (std::size_t I = 0; I < 8; ++I) {
    Xm[I] = axes.transpose() * X[I];
    X_.col(static_cast<int>(I)) = Xm[I];
  }
  for (std::size_t I = 0; I < 8; ++I) x_committed_.col(static_cast<int>(I)) = X[I];
  x_trial_ = x_committed_;
  auto checked_inverse = [&](const Vec3& s, double* det) {
    const Mat3 J = hex_jacobian(Xm, hex_parent_derivatives(s));
    *det = J.determinant();
    if (!(*det > 0.0))
      throw std::invalid_argument("solid-shell: Jacobian " + std::to_string(*det) + " <= 0 at (" + std::to_string(s(0)) + ", " +
                                  std::to_string(s(1)) + ", " + std::to_string(s(2)) + ") (inverted or badly ordered corners)");
    return Mat3(J.inverse());
  };
  double det0 = 0.0;
  const Voigt6x6 T0 = convective_to_material(checked_inverse(Vec3::Zero(), &det0));
  const double g = 1.0 / std::sqrt(3.0);
  for (std::size_t k = 0; k < zeta_.size(); ++k) {
    const double zeta = zeta_[k];
    for (int q = 0; q < 4; ++q) {
      PointGeometry pg;
      pg.s = Vec3(g * kColumn[q][0], g * kColumn[q][1], zeta);
      pg.level = static_cast<int>(k);
      double det = 0.0;
      pg.T = convective_to_material(checked_inverse(pg.s, &det));
      Eigen::Matrix<double, 6, kEnhanced> M = Eigen::Matrix<double, 6, kEnhanced>::Zero();
      const double xi = pg.s(0), eta = pg.s(1);
      M.row(2) << zeta, zeta * xi, zeta * eta, zeta * xi * eta;
      pg.Gamma = (det0 / det) * T0 * M;
      pg.weight = rule.weight[k] * det;
      volume0_ += pg.weight;
      geometry_.push_back(pg);
      points_.emplace_back(law);
    }
    Eigen::Vector4d ref;
    for (int m = 0; m < 4; ++m) {
      const Grad dN = hex_parent_derivatives(Vec3(kShearSample[m][0], kShearSample[m][1], zeta));
      ref(m) = tangent(X_, dN, m < 2 ? 0 : 1).dot(tangent(X_, dN, 2));
    }
    shear0_.push_back(ref);
  }
  g3_norm0_ = tangent(X_, hex_parent_derivatives(Vec3::Zero()), 2).norm();
}

namespace {
// The kinematics of one integration point: convective strain samples, interpolation weights,
// d e / d x of the convective strain e, and the log strain of E (material frame).
struct PointKinematics {
  Sample e11, e22, e12, e33;
  double w13[2], w23[2];
  Eigen::Matrix<double, 6, 24> Bc;
  LogStrain3 ls;
};
const Voigt6 kTrace = (Voigt6() << 1, 1, 1, 0, 0, 0).finished();

// The sampled transverse shears of a zeta level (reference values ref): e13 at eta = -1, +1,
// e23 at xi = -1, +1.
std::array<Sample, 4> shear_samples(const Eigen::Matrix<double, 3, 8>& x, double zeta, const Eigen::Vector4d& ref) {
  std::array<Sample, 4> shear;
  for (int m = 0; m < 4; ++m)
    shear[static_cast<std::size_t>(m)] = sample_product(x, hex_parent_derivatives(Vec3(kShearSample[m][0], kShearSample[m][1], zeta)), m < 2 ? 0 : 1, 2, ref(m));
  return shear;
}

// The kinematics at parent point s of the corners x (X the reference ones, T the point's
// convective-to-material transformation, Gamma its enhanced strains with parameters alpha).
PointStatus point_kinematics(const Eigen::Matrix<double, 3, 8>& x, const Eigen::Matrix<double, 3, 8>& X, const Vec3& s, const Voigt6x6& T,
                             const Eigen::Matrix<double, 6, SolidShell8::kEnhanced>& Gamma, const SolidShell8::EnhancedVector& alpha,
                             const std::array<Sample, 4>& shear, PointKinematics* k) {
  using RowU = Eigen::Matrix<double, 1, 24>;
  PointStatus status;
  const double xi = s(0), eta = s(1);
  const Grad dN = hex_parent_derivatives(s);
  const double det = hex_jacobian_determinant(x, dN) / hex_jacobian_determinant(X, dN);
  if (!(det > 0.0)) {
    status.ok = false;
    status.reason = std::isfinite(det) ? "element turned inside out (det F = " + std::to_string(det) + ")" : "non-finite positions";
    status.suggested_scale = 0.25;
    return status;
  }
  k->e11 = sample_product(x, dN, 0, 0, 0.0);
  k->e22 = sample_product(x, dN, 1, 1, 0.0);
  k->e12 = sample_product(x, dN, 0, 1, 0.0);
  const Vec3 G1 = tangent(X, dN, 0), G2 = tangent(X, dN, 1);
  k->w13[0] = 0.5 * (1.0 - eta);
  k->w13[1] = 0.5 * (1.0 + eta);
  k->w23[0] = 0.5 * (1.0 - xi);
  k->w23[1] = 0.5 * (1.0 + xi);
  Voigt6 e;
  e(0) = k->e11.value - 0.5 * G1.dot(G1);
  e(1) = k->e22.value - 0.5 * G2.dot(G2);
  e(3) = k->e12.value - G1.dot(G2);
  const Vec3 G3 = tangent(X, dN, 2);
  k->e33 = sample_product(x, dN, 2, 2, 0.5 * G3.dot(G3));
  e(2) = k->e33.value;
  e(4) = k->w13[0] * shear[0].value + k->w13[1] * shear[1].value;
  e(5) = k->w23[0] * shear[2].value + k->w23[1] * shear[3].value;
  auto set_row = [k](int r, const Grad& g) { k->Bc.row(r) = Eigen::Map<const RowU>(g.data()); };
  set_row(0, k->e11.grad);
  set_row(1, k->e22.grad);
  set_row(3, k->e12.grad);
  set_row(2, k->e33.grad);
  set_row(4, k->w13[0] * shear[0].grad + k->w13[1] * shear[1].grad);
  set_row(5, k->w23[0] * shear[2].grad + k->w23[1] * shear[3].grad);
  const Voigt6 E = T * e + Gamma * alpha;
  const PointStatus admissible = admissible_green_strain(E);
  if (!admissible.ok) return admissible;
  k->ls = log_strain_3d(E);
  return status;
}
}  // namespace

void SolidShell8::accumulate(const Eigen::Matrix<double, 3, 8>& x, const EnhancedVector& alpha, bool with_kuu, Sums* sums,
                             PointStatus* status) {
  using RowU = Eigen::Matrix<double, 1, 24>;
  using RowA = Eigen::Matrix<double, 1, kEnhanced>;
  *sums = Sums{};
  std::array<PointKinematics, 4> pk;
  // The block in x: Bc^T Mc Bc (its lower triangle where the material tangent is symmetric, else
  // all of it) and the rest (geometric and mean-dilatation parts).
  HexMatrix klow = HexMatrix::Zero(), kuu_rest = HexMatrix::Zero();
  for (std::size_t level = 0; level < zeta_.size(); ++level) {
    const double zeta = zeta_[level];
    const std::array<Sample, 4> shear = shear_samples(x, zeta, shear0_[level]);
    // The level's four in-plane points: their log strains and the mean volumetric strain.
    double volume = 0.0, theta = 0.0;
    RowU dtheta_u = RowU::Zero();  // d theta / d x
    RowA dtheta_a = RowA::Zero();  // d theta / d alpha
    for (std::size_t q = 0; q < 4; ++q) {
      const std::size_t p = 4 * level + q;
      const PointGeometry& pg = geometry_[p];
      PointKinematics& k = pk[q];
      const PointStatus kinematics = point_kinematics(x, X_, pg.s, pg.T, pg.Gamma, alpha, shear, &k);
      if (!kinematics.ok) {
        *status = kinematics;
        return;
      }
      // d E / d x = T Bc and d E / d alpha = Gamma: the trace of d eps / d (x, alpha) without
      // forming d E / d x.
      const Eigen::Matrix<double, 1, 6> trace_first = kTrace.transpose() * k.ls.first;
      volume += pg.weight;
      theta += pg.weight * kTrace.dot(k.ls.value);
      dtheta_u.noalias() += pg.weight * (trace_first * pg.T) * k.Bc;
      dtheta_a.noalias() += pg.weight * trace_first * pg.Gamma;
    }
    theta /= volume;
    dtheta_u /= volume;
    dtheta_a /= volume;
    // Mean dilatation: each point takes its own deviatoric log strain and the level's mean
    // volumetric one, and the stresses their own deviator and the level's mean pressure.
    std::array<Voigt6, 4> T;
    std::array<Voigt6x6, 4> D;
    double pressure = 0.0;
    for (std::size_t q = 0; q < 4; ++q) {
      const std::size_t p = 4 * level + q;
      const Voigt6 eps = pk[q].ls.value + kTrace * ((theta - kTrace.dot(pk[q].ls.value)) / 3.0);
      const PointStatus ps = points_[p].update_log(eps, &T[q], &D[q]);
      if (!ps.ok) {
        *status = ps;
        return;
      }
      pressure += geometry_[p].weight * kTrace.dot(T[q]);
    }
    pressure /= volume;
    // With A = (I - m m^T / 3) d eps / dE and Gbar = A BG + m dtheta / 3 the derivative of a point's
    // modified log strain (BG = d E / d (x, alpha) = [T Bc, Gamma]):
    //   Gbar^T D Gbar + BG^T L BG = BG^T (A^T D A + L) BG + (BG^T c dtheta + dtheta^T c^T BG) / 3
    //                               + (m^T D m / 9) dtheta^T dtheta,   c = A^T D m,
    // L the log strain's second derivative contracted with the point's stress. The blocks in x
    // are formed through the convective strain: (T Bc)^T M (T Bc) = Bc^T (T^T M T) Bc.
    // With a tangent D that is not symmetric (kinematic hardening) the second coupling term
    // dtheta^T c'^T BG / 3 takes c' = A^T D^T m instead of c (the u_u2, u_a2 sums).
    Eigen::Matrix<double, 24, 1> u_u = Eigen::Matrix<double, 24, 1>::Zero(), u_u2 = Eigen::Matrix<double, 24, 1>::Zero();
    EnhancedVector u_a = EnhancedVector::Zero(), u_a2 = EnhancedVector::Zero();
    double dmm = 0.0;
    for (std::size_t q = 0; q < 4; ++q) {
      const std::size_t p = 4 * level + q;
      const PointGeometry& pg = geometry_[p];
      const PointKinematics& k = pk[q];
      const double w = pg.weight;
      const Voigt6 Te = T[q] + kTrace * ((pressure - kTrace.dot(T[q])) / 3.0);  // conjugate to eps of this point
      const Voigt6 S = k.ls.first.transpose() * Te;
      const Voigt6 s = w * pg.T.transpose() * S;  // convective stress times the weight
      sums->fu.noalias() += k.Bc.transpose() * s;
      sums->ra.noalias() += w * pg.Gamma.transpose() * S;
      const Voigt6x6 A = k.ls.first - kTrace * (kTrace.transpose() * k.ls.first) / 3.0;
      const Voigt6 Dm = D[q] * kTrace;
      const Voigt6x6 M = w * (A.transpose() * D[q] * A + log_strain_3d_second(k.ls, Te));
      const Voigt6 c = w * (A.transpose() * Dm);
      u_u.noalias() += k.Bc.transpose() * (pg.T.transpose() * c);
      u_a.noalias() += pg.Gamma.transpose() * c;
      dmm += w * kTrace.dot(Dm);
      const Eigen::Matrix<double, 6, kEnhanced> MG = M * pg.Gamma;
      sums->kua.noalias() += k.Bc.transpose() * (pg.T.transpose() * MG);
      sums->kaa.noalias() += pg.Gamma.transpose() * MG;
      if (!symmetric_) {
        const Voigt6 c2 = w * (A.transpose() * (D[q].transpose() * kTrace));
        u_u2.noalias() += k.Bc.transpose() * (pg.T.transpose() * c2);
        u_a2.noalias() += pg.Gamma.transpose() * c2;
        sums->kau.noalias() += (pg.Gamma.transpose() * M * pg.T) * k.Bc;
      }
      if (!with_kuu) continue;
      const Voigt6x6 Mc = pg.T.transpose() * M * pg.T;
      const Eigen::Matrix<double, 6, 24> MB = Mc * k.Bc;
      if (symmetric_) {
        // Bc^T Mc Bc is symmetric: its lower triangle only, mirrored after the loop.
        for (int j = 0; j < 24; ++j)
          for (int i = j; i < 24; ++i) klow(i, j) += k.Bc.col(i).dot(MB.col(j));
      } else {
        klow.noalias() += k.Bc.transpose() * MB;
      }
      // Geometric part: the convective stress times the second derivatives of e.
      Eigen::Matrix<double, 8, 8> H = s(0) * second(k.e11, true) + s(1) * second(k.e22, true) + s(3) * second(k.e12, false);
      H += s(2) * second(k.e33, true);
      H += (s(4) * k.w13[0]) * second(shear[0], false) + (s(4) * k.w13[1]) * second(shear[1], false);
      H += (s(5) * k.w23[0]) * second(shear[2], false) + (s(5) * k.w23[1]) * second(shear[3], false);
      for (int I = 0; I < 8; ++I)
        for (int J = 0; J < 8; ++J)
          for (int i = 0; i < 3; ++i) kuu_rest(3 * I + i, 3 * J + i) += H(I, J);
    }
    const double d9 = dmm / 9.0;
    if (symmetric_) {
      sums->kua.noalias() += (u_u * dtheta_a + dtheta_u.transpose() * u_a.transpose()) / 3.0 + d9 * dtheta_u.transpose() * dtheta_a;
      sums->kaa.noalias() += (u_a * dtheta_a + dtheta_a.transpose() * u_a.transpose()) / 3.0 + d9 * dtheta_a.transpose() * dtheta_a;
      if (with_kuu) {
        const HexMatrix coupling = (u_u * dtheta_u) / 3.0;
        kuu_rest.noalias() += coupling + coupling.transpose() + d9 * dtheta_u.transpose() * dtheta_u;
      }
    } else {
      sums->kua.noalias() += (u_u * dtheta_a + dtheta_u.transpose() * u_a2.transpose()) / 3.0 + d9 * dtheta_u.transpose() * dtheta_a;
      sums->kau.noalias() += (u_a * dtheta_u + dtheta_a.transpose() * u_u2.transpose()) / 3.0 + d9 * dtheta_a.transpose() * dtheta_u;
      sums->kaa.noalias() += (u_a * dtheta_a + dtheta_a.transpose() * u_a2.transpose()) / 3.0 + d9 * dtheta_a.transpose() * dtheta_a;
      if (with_kuu) kuu_rest.noalias() += (u_u * dtheta_u + dtheta_u.transpose() * u_u2.transpose()) / 3.0 + d9 * dtheta_u.transpose() * dtheta_u;
    }
  }
  if (symmetric_) sums->kau = sums->kua.transpose();
  if (with_kuu) sums->kuu = kuu_rest + (symmetric_ ? HexMatrix(klow.selfadjointView<Eigen::Lower>().toDenseMatrix()) : klow);
}

PointStatus SolidShell8::evaluate(const HexCorners& xc, HexVector* f, HexMatrix* K) {
  PointStatus status;
  Eigen::Matrix<double, 3, 8> x;
  for (std::size_t I = 0; I < 8; ++I) x.col(static_cast<int>(I)) = xc[I];
  if (!x.allFinite()) {
    status.ok = false;
    status.reason = "non-finite positions";
    status.suggested_scale = 0.25;
    return status;
  }
  const Eigen::Matrix<double, 3, 8> dx = x - x_trial_;
  EnhancedVector alpha = alpha_trial_ + dalpha_trial_ * Eigen::Map<const Eigen::Matrix<double, 24, 1>>(dx.data());
  Sums sums;
  EnhancedVector step;
  Eigen::PartialPivLU<Eigen::Matrix<double, kEnhanced, kEnhanced>> lu;
  int it = 0;
  for (;; ++it) {
    accumulate(x, alpha, K != nullptr, &sums, &status);
    if (!status.ok) return status;
    lu.compute(sums.kaa);
    step = lu.solve(sums.ra);
    if (!step.allFinite()) {
      status.ok = false;
      status.reason = "solid-shell: singular enhanced-strain stiffness";
      status.suggested_scale = 0.25;
      return status;
    }
    // Exact tangents at the converged iterate: the enhanced parameters it converged to.
    if (exact_tangents_ || step.cwiseAbs().maxCoeff() <= enhanced_tolerance_) break;
    if (it + 1 == kMaxEnhancedIterations) {
      status.ok = false;
      status.reason = "solid-shell: the enhanced strains did not converge (last change " + std::to_string(step.cwiseAbs().maxCoeff()) + ")";
      status.suggested_scale = 0.5;
      return status;
    }
    alpha -= step;
  }
  last_iterations_ = it + 1;
  // The residual left in the enhanced equations, removed to first order.
  if (f) *f = sums.fu - sums.kua * step;
  const Eigen::Matrix<double, kEnhanced, 24> kaa_inv_kau = lu.solve(sums.kau);
  if (K) *K = sums.kuu - sums.kua * kaa_inv_kau;
  if (sensitivity_count_ > 0) {
    kaa_inverse_ = lu.inverse();
    kua_ = sums.kua;
    dalpha_du_ = -kaa_inv_kau;
  }
  if (exact_tangents_) return status;
  alpha_trial_ = alpha;
  x_trial_ = x;
  dalpha_trial_ = -kaa_inv_kau;
  thickness_ratio_trial_ = tangent(x, hex_parent_derivatives(Vec3::Zero()), 2).norm() / g3_norm0_;
  return status;
}

void SolidShell8::commit() {
  for (auto& p : points_) p.commit();
  dthickness_ = dthickness_trial_;
  alpha_ = alpha_trial_;
  x_committed_ = x_trial_;
  dalpha_ = dalpha_trial_;
  thickness_ratio_ = thickness_ratio_trial_;
}

void SolidShell8::revert() {
  for (auto& p : points_) p.revert();
  dthickness_trial_ = dthickness_;
  alpha_trial_ = alpha_;
  x_trial_ = x_committed_;
  dalpha_trial_ = dalpha_;
  thickness_ratio_trial_ = thickness_ratio_;
}

double SolidShell8::elastic_energy() const {
  double sum = 0.0;
  for (std::size_t p = 0; p < points_.size(); ++p) sum += geometry_[p].weight * points_[p].elastic_energy_density();
  return sum;
}

double SolidShell8::plastic_work() const {
  double sum = 0.0;
  for (std::size_t p = 0; p < points_.size(); ++p) sum += geometry_[p].weight * points_[p].plastic_work_density();
  return sum;
}

double SolidShell8::max_eqps() const {
  double m = 0.0;
  for (const auto& p : points_) m = std::max(m, p.committed().eqps);
  return m;
}

Voigt6 SolidShell8::mean_stress() const {
  Voigt6 s = Voigt6::Zero();
  for (std::size_t p = 0; p < points_.size(); ++p) s += (geometry_[p].weight / volume0_) * points_[p].committed().stress;
  return s;
}

void SolidShell8::save_state(io::BinaryWriter& w) const {
  for (const auto& p : points_) p.save_state(w);
  w.vector(alpha_);
  w.vector(Eigen::Map<const Eigen::VectorXd>(x_committed_.data(), 24));
  w.vector(Eigen::Map<const Eigen::VectorXd>(dalpha_.data(), kEnhanced * 24));
  w.f64(thickness_ratio_);
}

void SolidShell8::load_state(io::BinaryReader& r) {
  for (auto& p : points_) p.load_state(r);
  const Eigen::VectorXd a = r.vector(), xc = r.vector(), da = r.vector();
  if (a.size() != kEnhanced || xc.size() != 24 || da.size() != kEnhanced * 24)
    throw io::ArchiveError("solid-shell: expected " + std::to_string(kEnhanced) + " enhanced parameters, 24 corner coordinates and their " +
                           std::to_string(kEnhanced * 24) + " derivatives");
  alpha_ = alpha_trial_ = a;
  x_committed_ = x_trial_ = Eigen::Map<const Eigen::Matrix<double, 3, 8>>(xc.data());
  dalpha_ = dalpha_trial_ = Eigen::Map<const Eigen::Matrix<double, kEnhanced, 24>>(da.data());
  thickness_ratio_ = thickness_ratio_trial_ = r.f64();
}

void SolidShell8::enable_sensitivities(const SolidSensitivityLaw& law, int count) {
  (void)law;  // the points read it at every pass
  if (count < 1 || count > material::kSensitivitySlots)
    throw std::invalid_argument("solid-shell sensitivities: " + std::to_string(count) + " parameters");
  sensitivity_count_ = count;
  for (auto& p : points_) p.enable_sensitivities(false);  // no stabilisation built on the tangent
  dra_.setZero();
  dthickness_ = dthickness_trial_ = material::SensitivityRow::Zero();
}

bool SolidShell8::tangent_was_exact() const {
  for (const auto& p : points_)
    if (!p.tangent_was_exact()) return false;
  return true;
}

void SolidShell8::set_exact_tangents(bool exact) {
  exact_tangents_ = exact;
  for (auto& p : points_) p.set_exact_tangents(exact);
}

PointStatus SolidShell8::sensitivities(const HexCorners& xc, const SolidSensitivityLaw& law, const HexSensitivities* du, HexSensitivities* load) {
  using material::derivatives_of;
  using SensRow = material::SensitivityRow;
  using EnhancedColumns = Eigen::Matrix<double, kEnhanced, material::kSensitivitySlots>;
  if (sensitivity_count_ == 0) throw std::logic_error("SolidShell8::sensitivities before enable_sensitivities");
  Eigen::Matrix<double, 3, 8> x;
  for (std::size_t I = 0; I < 8; ++I) x.col(static_cast<int>(I)) = xc[I];
  // The enhanced parameters of the converged iterate, and with du their derivatives from the
  // condensed equations (d r_a / d p from the pseudo-load's pass).
  const EnhancedVector& alpha = alpha_trial_;
  EnhancedColumns dalpha = EnhancedColumns::Zero();
  if (du) dalpha = dalpha_du_ * *du - kaa_inverse_ * dra_;
  HexSensitivities dfu = HexSensitivities::Zero();
  EnhancedColumns dra = EnhancedColumns::Zero();
  std::array<PointKinematics, 4> pk;
  std::array<SensColumns6, 4> dls;
  std::array<Voigt6S, 4> T;
  for (std::size_t level = 0; level < zeta_.size(); ++level) {
    const std::array<Sample, 4> shear = shear_samples(x, zeta_[level], shear0_[level]);
    // The points' log strains as accumulate() forms them, and with du their derivatives.
    double volume = 0.0, theta = 0.0;
    SensRow dtheta = SensRow::Zero();
    for (std::size_t q = 0; q < 4; ++q) {
      const PointGeometry& pg = geometry_[4 * level + q];
      const PointStatus kinematics = point_kinematics(x, X_, pg.s, pg.T, pg.Gamma, alpha, shear, &pk[q]);
      if (!kinematics.ok) return kinematics;
      volume += pg.weight;
      theta += pg.weight * kTrace.dot(pk[q].ls.value);
      if (du) {
        dls[q] = pk[q].ls.first * (pg.T * (pk[q].Bc * *du) + pg.Gamma * dalpha);
        dtheta += pg.weight * kTrace.transpose() * dls[q];
      }
    }
    theta /= volume;
    dtheta /= volume;
    SensRow dpressure = SensRow::Zero();
    std::array<SensColumns6, 4> dT;
    for (std::size_t q = 0; q < 4; ++q) {
      const std::size_t p = 4 * level + q;
      const Voigt6 eps = pk[q].ls.value + kTrace * ((theta - kTrace.dot(pk[q].ls.value)) / 3.0);
      SensColumns6 deps;
      if (du) deps = dls[q] + kTrace * ((dtheta - kTrace.transpose() * dls[q]) / 3.0);
      const PointStatus ps = points_[p].sensitivities(law, eps, du ? &deps : nullptr, load ? &T[q] : nullptr);
      if (!ps.ok) return ps;
      if (!load) continue;
      for (int i = 0; i < 6; ++i) dT[q].row(i) = derivatives_of(T[q](i));
      dpressure += geometry_[p].weight * kTrace.transpose() * dT[q];
    }
    if (!load) continue;
    dpressure /= volume;
    // At fixed corners and enhanced parameters only the stresses move: each point's deviator and
    // the level's mean pressure.
    for (std::size_t q = 0; q < 4; ++q) {
      const PointGeometry& pg = geometry_[4 * level + q];
      const SensColumns6 dTe = dT[q] + kTrace * ((dpressure - kTrace.transpose() * dT[q]) / 3.0);
      const SensColumns6 dS = pk[q].ls.first.transpose() * dTe;
      dfu.noalias() += pk[q].Bc.transpose() * (pg.weight * pg.T.transpose() * dS);
      dra.noalias() += pg.weight * pg.Gamma.transpose() * dS;
    }
  }
  if (load) {
    dra_ = dra;
    *load = dfu - kua_ * (kaa_inverse_ * dra);
    load->rightCols(material::kSensitivitySlots - sensitivity_count_).setZero();
  }
  if (du) {
    // |g_3| / |G_3| at the centre: d|g_3| = g_3 . dg_3 / |g_3|.
    const Row8 dn = hex_parent_derivatives(Vec3::Zero()).row(2);
    const Vec3 g3 = x * dn.transpose();
    dthickness_trial_.setZero();
    for (int k = 0; k < sensitivity_count_; ++k) {
      Vec3 dg3 = Vec3::Zero();
      for (int I = 0; I < 8; ++I) dg3 += dn(I) * du->block<3, 1>(3 * I, k);
      dthickness_trial_(k) = g3.dot(dg3) / (g3.norm() * g3_norm0_);
    }
  }
  return {};
}

void SolidShell8::save_sensitivities(io::BinaryWriter& w, int count) const {
  for (const auto& p : points_) p.save_sensitivities(w, count);
  save_columns(w, dthickness_, count);
}

void SolidShell8::load_sensitivities(io::BinaryReader& r, int count) {
  if (count != sensitivity_count_) throw std::logic_error("SolidShell8::load_sensitivities: another parameter count than enabled");
  for (auto& p : points_) p.load_sensitivities(r, count);
  load_columns(r, "solid-shell thickness", count, &dthickness_);
  dthickness_trial_ = dthickness_;
}

}  // namespace spifit::element
