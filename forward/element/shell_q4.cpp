#include "forward/element/shell_q4.hpp"

#include "forward/element/director_dofs.hpp"
#include "forward/element/quad_shape.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <array>
#include <cmath>
#include <stdexcept>

namespace spifit::element {
namespace {

// Tying points of the MITC4 transverse shear: B (0,-1) and D (0,1) carry gamma_xi,
// A (-1,0) and C (1,0) carry gamma_eta.
constexpr double kTieXi[4] = {0.0, 0.0, -1.0, 1.0};
constexpr double kTieEta[4] = {-1.0, 1.0, 0.0, 0.0};
constexpr int kTieDir[4] = {0, 0, 1, 1};

}  // namespace

// Mid-surface tangents f_a = dx/dy_a and director derivatives dd_a = dd/dy_a at a Gauss point
// (y_a: element frame), and the tangents g_a that the in-plane shear strain uses: the element
// centre's with centre_membrane_shear (selective reduced integration), else f_a.
struct PointKinematics {
  Eigen::Vector3d f0, f1, dd0, dd1, g0, g1;
};

namespace {

PointKinematics point_kinematics(const Eigen::Matrix<double, 2, 4>& dN, const Eigen::Matrix<double, 2, 4>& dN_shear,
                                 bool centre_shear, const NodeVectors& x, const NodeVectors& d) {
  PointKinematics k;
  k.f0 = combine(dN.row(0).transpose(), x);
  k.f1 = combine(dN.row(1).transpose(), x);
  k.dd0 = combine(dN.row(0).transpose(), d);
  k.dd1 = combine(dN.row(1).transpose(), d);
  k.g0 = centre_shear ? combine(dN_shear.row(0).transpose(), x) : k.f0;
  k.g1 = centre_shear ? combine(dN_shear.row(1).transpose(), x) : k.f1;
  return k;
}

// The helpers below take the element's private point types (ShellQ4::PointGeometry as Point,
// ShellQ4::TyingPoint as Tying) by deduction. pg is the Gauss point, ps the point of the
// in-plane shear (the centre or pg).

// Membrane Green-Lagrange strains e and bending strains kappa (engineering shear), both from
// the reference configuration: e_ab = (f_a . f_b - F_a . F_b) / 2 (shear 2 e_01, from ps) and
// kappa = (f_0 . dd_0, f_1 . dd_1, f_0 . dd_1 + f_1 . dd_0) - its reference value.
template <class Point>
void shell_strains(const Point& pg, const Point& ps, const PointKinematics& k, Vec3& e, Vec3& kappa) {
  e << 0.5 * (k.f0.squaredNorm() - pg.F0ref.squaredNorm()), 0.5 * (k.f1.squaredNorm() - pg.F1ref.squaredNorm()),
      k.g0.dot(k.g1) - ps.F0ref.dot(ps.F1ref);
  kappa << k.f0.dot(k.dd0), k.f1.dot(k.dd1), k.f0.dot(k.dd1) + k.f1.dot(k.dd0);
  kappa -= pg.kappa_ref;
}

// The centre's strains (e, kappa), element frame, and its kinematics k.
template <class Point>
Vec6 centre_strains(const Point& pc, const NodeVectors& x, const NodeVectors& d, PointKinematics* k) {
  *k = point_kinematics(pc.dN, pc.dN, false, x, d);
  Vec3 e, kappa;
  shell_strains(pc, pc, *k, e, kappa);
  Vec6 out;
  out << e, kappa;
  return out;
}

// One Gauss point at the nodes x, d: its in-plane shear point ps (the centre with
// centre_membrane_shear), kinematics, strains and the tying points' interpolation weights c.
template <class Point>
struct PointStrains {
  const Point& pg;
  const Point& ps;
  PointKinematics k;
  Vec3 e, kappa;
  double c[4];
};

template <class Point>
PointStrains<Point> point_strains(const Point& pg, const Point& centre, bool centre_shear, const NodeVectors& x, const NodeVectors& d) {
  const Point& ps = centre_shear ? centre : pg;
  PointStrains<Point> s{pg, ps, point_kinematics(pg.dN, ps.dN, centre_shear, x, d), Vec3(), Vec3(),
                        {0.5 * (1.0 - pg.eta), 0.5 * (1.0 + pg.eta), 0.5 * (1.0 - pg.xi), 0.5 * (1.0 + pg.xi)}};
  shell_strains(pg, ps, s.k, s.e, s.kappa);
  return s;
}

ElementStatus point_failure(int point, const SectionStatus& ss) {
  ElementStatus status;
  status.ok = false;
  status.point = point;
  status.layer = ss.layer;
  status.reason = ss.reason;
  status.suggested_scale = ss.suggested_scale;
  return status;
}

// Section forces and their tangent from the material frame to the element frame: with
// q6 = diag(Q, Q), s6 = q6^T s6m and d6 = q6^T d6m q6, block by block.
void to_element_frame(const Eigen::Matrix3d& Q, const Vec6& s6m, const Mat6& d6m, bool tangent, Vec6& s6, Mat6& d6) {
  s6.head<3>().noalias() = Q.transpose() * s6m.head<3>();
  s6.tail<3>().noalias() = Q.transpose() * s6m.tail<3>();
  if (tangent)
    for (int bi = 0; bi < 2; ++bi)
      for (int bj = 0; bj < 2; ++bj)
        d6.block<3, 3>(3 * bi, 3 * bj).noalias() = Q.transpose() * (d6m.block<3, 3>(3 * bi, 3 * bj) * Q);
}

// B = d(e, kappa, gamma)/dp, 8 x 24 (B zero on entry). The MITC4 rows interpolate the tying
// points' derivatives with the weights c and map them from natural to element axes with K.
template <class Point, class Tying>
void strain_operator(const Point& pg, const Point& ps, const std::array<Tying, 4>& tying, const PointKinematics& k,
                     const double (&c)[4], const std::array<Eigen::Vector3d, 4>& a_t,
                     const std::array<Eigen::Vector3d, 4>& d_t, Eigen::Matrix<double, 8, 24>& B) {
  Eigen::Matrix<double, 2, 24> Bnat = Eigen::Matrix<double, 2, 24>::Zero();
  for (int I = 0; I < 4; ++I) {
    const double n0 = pg.dN(0, I), n1 = pg.dN(1, I);
    const int cx = 6 * I, cd = 6 * I + 3;
    B.block<1, 3>(0, cx) = n0 * k.f0.transpose();
    B.block<1, 3>(1, cx) = n1 * k.f1.transpose();
    B.block<1, 3>(2, cx) = (ps.dN(0, I) * k.g1 + ps.dN(1, I) * k.g0).transpose();
    B.block<1, 3>(3, cx) = n0 * k.dd0.transpose();
    B.block<1, 3>(4, cx) = n1 * k.dd1.transpose();
    B.block<1, 3>(5, cx) = (n0 * k.dd1 + n1 * k.dd0).transpose();
    B.block<1, 3>(3, cd) = n0 * k.f0.transpose();
    B.block<1, 3>(4, cd) = n1 * k.f1.transpose();
    B.block<1, 3>(5, cd) = (n1 * k.f0 + n0 * k.f1).transpose();
    for (std::size_t t = 0; t < 4; ++t) {
      const int row = kTieDir[t];
      Bnat.block<1, 3>(row, cx) += c[t] * tying[t].dN(I) * d_t[t].transpose();
      Bnat.block<1, 3>(row, cd) += c[t] * tying[t].N(I) * a_t[t].transpose();
    }
  }
  B.bottomRows<2>() = pg.K * Bnat;
}

// rp += B^T (s6, Q) without forming B (strain_operator's rows; the residual of the one-point
// element, which needs five of these per element and no tangent in explicit runs).
template <class Point, class Tying>
void add_strain_operator_transpose(const Point& pg, const Point& ps, const std::array<Tying, 4>& tying, const PointKinematics& k,
                                   const double (&c)[4], const std::array<Eigen::Vector3d, 4>& a_t,
                                   const std::array<Eigen::Vector3d, 4>& d_t, const Vec6& s6, const Eigen::Vector2d& Q, Vec24& rp) {
  const Eigen::Vector2d qn = pg.K.transpose() * Q;  // B_shear^T Q = Bnat^T K^T Q
  for (int I = 0; I < 4; ++I) {
    const double n0 = pg.dN(0, I), n1 = pg.dN(1, I);
    Eigen::Vector3d fx = (n0 * s6(0)) * k.f0 + (n1 * s6(1)) * k.f1 + s6(2) * (ps.dN(0, I) * k.g1 + ps.dN(1, I) * k.g0) +
                         (n0 * s6(3) + n1 * s6(5)) * k.dd0 + (n1 * s6(4) + n0 * s6(5)) * k.dd1;
    Eigen::Vector3d fd = (n0 * s6(3) + n1 * s6(5)) * k.f0 + (n1 * s6(4) + n0 * s6(5)) * k.f1;
    for (std::size_t t = 0; t < 4; ++t) {
      const double q = qn(kTieDir[t]) * c[t];
      fx += (q * tying[t].dN(I)) * d_t[t];
      fd += (q * tying[t].N(I)) * a_t[t];
    }
    rp.segment<3>(6 * I) += fx;
    rp.segment<3>(6 * I + 3) += fd;
  }
}

// Tangent of one Gauss point added to kp: material part B^T D B with D = diag(d6, ks, ks), and
// the geometric part (the second derivatives of e, kappa and gamma are scalars x identity)
// from the section forces s6 and the shear forces Q.
// symmetric: d6 is symmetric (no kinematic hardening), so B^T D B is, and only its node blocks
// (I, J) with I <= J are added (the caller mirrors them: mirror_upper_blocks).
template <class Point, class Tying>
void add_point_tangent(const Point& pg, const Point& ps, const std::array<Tying, 4>& tying, const Vec6& s6,
                       const Mat6& d6, const Eigen::Vector2d& Q, double ks, const double (&c)[4],
                       const Eigen::Matrix<double, 8, 24>& B, bool symmetric, Mat24& kp) {
  // Coefficient-wise (lazy) products; at 24 x 8 x 24 Eigen's blocked GEMM spent more time
  // packing than multiplying.
  Eigen::Matrix<double, 8, 24> DB;
  DB.topRows<6>().noalias() = (pg.weight * d6).lazyProduct(B.topRows<6>());
  DB.bottomRows<2>() = (pg.weight * ks) * B.bottomRows<2>();
  if (symmetric) {
    for (int I = 0; I < 4; ++I)
      for (int J = I; J < 4; ++J) kp.block<6, 6>(6 * I, 6 * J).noalias() += B.middleCols<6>(6 * I).transpose().lazyProduct(DB.middleCols<6>(6 * J));
  } else {
    kp.noalias() += B.transpose().lazyProduct(DB);
  }
  const Eigen::Vector2d qn = pg.K.transpose() * Q;  // Q . gamma = qn . gamma_nat
  for (int I = 0; I < 4; ++I) {
    for (int Jn = 0; Jn < 4; ++Jn) {
      const double a0 = pg.dN(0, I) * pg.dN(0, Jn), a1 = pg.dN(1, I) * pg.dN(1, Jn);
      const double a2 = pg.dN(0, I) * pg.dN(1, Jn) + pg.dN(1, I) * pg.dN(0, Jn);
      const double s2 = ps.dN(0, I) * ps.dN(1, Jn) + ps.dN(1, I) * ps.dN(0, Jn);
      const double gxx = s6(0) * a0 + s6(1) * a1 + s6(2) * s2;
      double gxd = s6(3) * a0 + s6(4) * a1 + s6(5) * a2;
      for (std::size_t t = 0; t < 4; ++t) gxd += qn(kTieDir[t]) * c[t] * tying[t].dN(I) * tying[t].N(Jn);
      for (int k = 0; k < 3; ++k) {
        kp(6 * I + k, 6 * Jn + k) += pg.weight * gxx;
        kp(6 * I + k, 6 * Jn + 3 + k) += pg.weight * gxd;
        kp(6 * Jn + 3 + k, 6 * I + k) += pg.weight * gxd;
      }
    }
  }
}

}  // namespace

ShellQ4::ShellQ4(const NodeVectors& X, const NodeVectors& D, double thickness, const ShellSection::Law& law,
                 const ThicknessRule& rule, const ShellOptions& options)
    : options_(options), h0_(thickness) {
  if (!(thickness > 0.0)) throw std::invalid_argument("shell thickness must be > 0");
  const auto& p = law.params();
  shear_modulus_ = p.E / (2.0 * (1.0 + p.nu));
  symmetric_material_ = !p.kinematic.active();
  const double g = 1.0 / std::sqrt(3.0);
  const double gxi[4] = {-g, g, g, -g}, geta[4] = {-g, -g, g, g};
  // Element frame: e1 along the xi direction at the centre, projected on the tangent plane.
  const Eigen::Vector3d a0_centre = combine(quad_shape_derivatives(0.0, 0.0).row(0).transpose(), X);
  const auto setup = [&](PointGeometry& pg) {
    const Eigen::Matrix<double, 2, 4> dn = quad_shape_derivatives(pg.xi, pg.eta);
    const Eigen::Vector3d a0 = combine(dn.row(0).transpose(), X), a1 = combine(dn.row(1).transpose(), X);
    const Eigen::Vector3d normal = a0.cross(a1);
    if (!(normal.norm() > 1e-14 * a0.squaredNorm())) throw std::invalid_argument("degenerate shell element (zero area)");
    const Eigen::Vector3d n0 = normal.normalized();
    const Eigen::Vector3d e1 = (a0_centre - a0_centre.dot(n0) * n0).normalized();
    const Eigen::Vector3d e2 = n0.cross(e1);
    // Material frame m1 = rolling direction projected on the tangent plane.
    Eigen::Vector3d m1 = options.material_axis - options.material_axis.dot(n0) * n0;
    if (m1.norm() < 0.1) m1 = e1;  // rolling direction almost normal to the shell
    m1.normalize();
    const double c = m1.dot(e1), s = m1.dot(e2);
    pg.Q << c * c, s * s, c * s, s * s, c * c, -c * s, -2.0 * c * s, 2.0 * c * s, c * c - s * s;
    Eigen::Matrix2d J;
    J << a0.dot(e1), a0.dot(e2), a1.dot(e1), a1.dot(e2);
    const double det = J.determinant();
    if (!(det > 0.0)) throw std::invalid_argument("shell element with non-positive area Jacobian");
    pg.K = J.inverse();
    pg.dN = pg.K * dn;
    pg.weight = det;
    pg.F0ref = combine(pg.dN.row(0).transpose(), X);
    pg.F1ref = combine(pg.dN.row(1).transpose(), X);
    const Eigen::Vector3d dd0 = combine(pg.dN.row(0).transpose(), D), dd1 = combine(pg.dN.row(1).transpose(), D);
    pg.kappa_ref << pg.F0ref.dot(dd0), pg.F1ref.dot(dd1), pg.F0ref.dot(dd1) + pg.F1ref.dot(dd0);
  };
  for (int q = 0; q < 4; ++q) {
    PointGeometry& pg = points_[static_cast<std::size_t>(q)];
    pg.xi = gxi[q];
    pg.eta = geta[q];
    setup(pg);
    area_ += pg.weight;
  }
  setup(centre_);
  // Directors must agree with the element's orientation (consistently numbered mesh, no kink
  // sharper than 60 degrees between neighbouring elements).
  for (int i = 0; i < 4; ++i) {
    const Eigen::Matrix<double, 2, 4> dn = quad_shape_derivatives(kNodeXi[i], kNodeEta[i]);
    const Eigen::Vector3d n = combine(dn.row(0).transpose(), X).cross(combine(dn.row(1).transpose(), X));
    if (!(n.normalized().dot(D[static_cast<std::size_t>(i)]) > 0.5))
      throw std::invalid_argument("node " + std::to_string(i) +
                                  ": director at more than 60 deg from the element normal (inconsistent orientation of neighbouring elements?)");
  }
  for (int t = 0; t < 4; ++t) {
    TyingPoint& tp = tying_[static_cast<std::size_t>(t)];
    tp.N = quad_shape(kTieXi[t], kTieEta[t]);
    tp.dN = quad_shape_derivatives(kTieXi[t], kTieEta[t]).row(kTieDir[t]).transpose();
    tp.gamma_ref = combine(tp.dN, X).dot(combine(tp.N, D));
  }
  const bool reduced = options_.hourglass_stiffness > 0.0;
  if (!(std::isfinite(options_.hourglass_stiffness) && options_.hourglass_stiffness >= 0.0))
    throw std::invalid_argument("hourglass stiffness must be a finite fraction >= 0");
  sections_.assign(reduced ? 1 : 4, ShellSection(law, rule, thickness));
  for (ShellSection& sec : sections_) sec.set_layer_tangents(options_.layer_tangents);
  if (reduced) {
    // The law's plane-stress isotropic elasticity (the same in every in-plane frame, engineering
    // shear): membrane h0 C, bending h0^3/12 C.
    const Eigen::Matrix3d c = law.elastic_matrix();
    hourglass_stiffness_.topLeftCorner<3, 3>() = options_.hourglass_stiffness * thickness * c;
    hourglass_stiffness_.bottomRightCorner<3, 3>() = options_.hourglass_stiffness * thickness * thickness * thickness / 12.0 * c;
  }
}

ShellQ4::TransverseShear ShellQ4::transverse_shear(const NodeVectors& x, const NodeVectors& d) const {
  TransverseShear out;
  std::array<double, 4> gamma_t{};
  for (std::size_t t = 0; t < 4; ++t) {
    out.a_t[t] = combine(tying_[t].dN, x);
    out.d_t[t] = combine(tying_[t].N, d);
    gamma_t[t] = out.a_t[t].dot(out.d_t[t]) - tying_[t].gamma_ref;
  }
  for (std::size_t q = 0; q < 4; ++q) {
    const PointGeometry& pg = points_[q];
    const double c[4] = {0.5 * (1.0 - pg.eta), 0.5 * (1.0 + pg.eta), 0.5 * (1.0 - pg.xi), 0.5 * (1.0 + pg.xi)};
    const Eigen::Vector2d gamma_nat(c[0] * gamma_t[0] + c[1] * gamma_t[1], c[2] * gamma_t[2] + c[3] * gamma_t[3]);
    out.gamma[q] = pg.K * gamma_nat;
  }
  return out;
}

std::array<Vec6, 4> ShellQ4::strain_variation(const NodeVectors& x, const NodeVectors& d, const Vec6& centre,
                                              std::array<PointKinematics, 4>* kinematics) const {
  std::array<Vec6, 4> out;
  for (std::size_t q = 0; q < 4; ++q) {
    const PointGeometry& pg = points_[q];
    const PointGeometry& ps = options_.centre_membrane_shear ? centre_ : pg;
    const PointKinematics k = point_kinematics(pg.dN, ps.dN, options_.centre_membrane_shear, x, d);
    if (kinematics) (*kinematics)[q] = k;
    Vec3 e, kappa;
    shell_strains(pg, ps, k, e, kappa);
    out[q] << e, kappa;
    out[q] -= centre;
  }
  return out;
}

ElementEnergy ShellQ4::energy(const NodeVectors& x, const NodeVectors& d) const {
  ElementEnergy out;
  const double ks = options_.shear_factor * shear_modulus_ * h0_;
  const TransverseShear shear = transverse_shear(x, d);
  for (std::size_t q = 0; q < 4; ++q) {
    const double w = points_[q].weight;
    out.transverse_shear += w * 0.5 * ks * shear.gamma[q].squaredNorm();
    if (sections_.size() == 4) {
      const SectionEnergy se = sections_[q].energy();
      out.elastic += w * se.elastic;
      out.plastic += w * se.plastic;
    }
  }
  if (sections_.size() == 1) {
    // The centre's section over the whole area, and the hourglass part.
    const SectionEnergy se = sections_[0].energy();
    out.elastic += area_ * se.elastic;
    out.plastic += area_ * se.plastic;
    PointKinematics k;
    const std::array<Vec6, 4> dv = strain_variation(x, d, centre_strains(centre_, x, d, &k));
    for (std::size_t q = 0; q < 4; ++q) out.elastic += points_[q].weight * 0.5 * dv[q].dot(hourglass_stiffness_ * dv[q]);
  }
  return out;
}

double ShellQ4::reference_area() const { return area_; }

void ShellQ4::save_state(io::BinaryWriter& w) const {
  for (const auto& sec : sections_) sec.save_state(w);
}

void ShellQ4::load_state(io::BinaryReader& r) {
  for (auto& sec : sections_) sec.load_state(r);
}

void ShellQ4::save_sensitivities(io::BinaryWriter& w, int count) const {
  for (const auto& sec : sections_) sec.save_sensitivities(w, count);
}

void ShellQ4::load_sensitivities(io::BinaryReader& r, int count) {
  for (auto& sec : sections_) sec.load_sensitivities(r, count);
}

ElementStatus ShellQ4::compute(const NodeVectors& x, const NodeVectors& d, Vec24* residual, Mat24* tangent) {
  if (sections_.size() == 1) return compute_reduced(x, d, residual, tangent);
  Vec24 rp = Vec24::Zero();  // derivative with respect to p = (x_I, d_I) per node
  Mat24 kp;
  if (tangent) kp.setZero();
  const double ks = options_.shear_factor * shear_modulus_ * h0_;

  // Tying-point shear strains and their derivatives (shared by the four Gauss points).
  const TransverseShear shear = transverse_shear(x, d);

  for (std::size_t q = 0; q < 4; ++q) {
    // In-plane shear from the centre (or from this point); c: the tying points' weights here.
    const auto p = point_strains(points_[q], centre_, options_.centre_membrane_shear, x, d);
    const PointGeometry& pg = p.pg;
    const PointGeometry& ps = p.ps;
    const PointKinematics& k = p.k;
    const Vec3 &e = p.e, &kappa = p.kappa;
    const double(&c)[4] = p.c;
    const Eigen::Vector2d& gamma = shear.gamma[q];

    // The layers work in the material frame: e_m = Q e, (N, M) = Q^T (N_m, M_m).
    Vec6 s6m;
    Mat6 d6m = Mat6::Zero();
    const SectionStatus ss = sections_[q].update(pg.Q * e, pg.Q * kappa, &s6m, tangent ? &d6m : nullptr);
    if (!ss.ok) return point_failure(static_cast<int>(q), ss);
    Vec6 s6;
    Mat6 d6;
    to_element_frame(pg.Q, s6m, d6m, tangent != nullptr, s6, d6);
    const Eigen::Vector2d Q = ks * gamma;

    Eigen::Matrix<double, 8, 24> B = Eigen::Matrix<double, 8, 24>::Zero();
    strain_operator(pg, ps, tying_, k, c, shear.a_t, shear.d_t, B);
    rp.noalias() += pg.weight * (B.topRows<6>().transpose() * s6 + B.bottomRows<2>().transpose() * Q);
    if (tangent) add_point_tangent(pg, ps, tying_, s6, d6, Q, ks, c, B, symmetric_material_, kp);
  }

  // With a symmetric material tangent the node blocks below the diagonal are mirrored from
  // those above (in kp's material part here, in ku's director transformation below).
  if (tangent && symmetric_material_) mirror_upper_blocks(kp);
  return dof_results(d, rp, tangent ? &kp : nullptr, symmetric_material_, options_.drilling_factor, area_, residual, tangent);
}

ElementStatus ShellQ4::compute_reduced(const NodeVectors& x, const NodeVectors& d, Vec24* residual, Mat24* tangent) {
  const double ks = options_.shear_factor * shear_modulus_ * h0_;
  const TransverseShear shear = transverse_shear(x, d);
  const PointGeometry& pc = centre_;
  PointKinematics kc;
  const Vec6 ec = centre_strains(pc, x, d, &kc);

  // The layers at the centre, weighted with the whole area.
  Vec6 s6m;
  Mat6 d6m = Mat6::Zero();
  const SectionStatus ss = sections_[0].update(pc.Q * ec.head<3>(), pc.Q * ec.tail<3>(), &s6m, tangent ? &d6m : nullptr);
  if (!ss.ok) return point_failure(0, ss);
  Vec6 s6;
  Mat6 d6;
  to_element_frame(pc.Q, s6m, d6m, tangent != nullptr, s6, d6);

  // Energy area psi(e_c) + sum_q w_q (dv_q . H dv_q) / 2 with dv_q = e_q - e_c, and the MITC4
  // shear at the four points: its gradient is area B_c^T s6 + sum_q w_q B_q^T (H dv_q + shear)
  // - B_c^T sum_q w_q H dv_q.
  const double cc[4] = {0.5, 0.5, 0.5, 0.5};
  Eigen::Matrix<double, 8, 24> Bc;
  if (tangent) {
    Bc.setZero();
    strain_operator(pc, pc, tying_, kc, cc, shear.a_t, shear.d_t, Bc);
  }
  std::array<PointKinematics, 4> kq;
  const std::array<Vec6, 4> dv = strain_variation(x, d, ec, &kq);
  Vec6 centre_force = area_ * s6;
  Vec24 rp = Vec24::Zero();
  Mat24 kp;
  if (tangent) kp.setZero();
  for (std::size_t q = 0; q < 4; ++q) {
    const PointGeometry& pg = points_[q];
    const PointGeometry& ps = options_.centre_membrane_shear ? centre_ : pg;
    const double c[4] = {0.5 * (1.0 - pg.eta), 0.5 * (1.0 + pg.eta), 0.5 * (1.0 - pg.xi), 0.5 * (1.0 + pg.xi)};
    const Vec6 hdv = hourglass_stiffness_ * dv[q];
    centre_force -= pg.weight * hdv;
    const Eigen::Vector2d Q = ks * shear.gamma[q];
    add_strain_operator_transpose(pg, ps, tying_, kq[q], c, shear.a_t, shear.d_t, Vec6(pg.weight * hdv), Eigen::Vector2d(pg.weight * Q), rp);
    if (tangent) {
      // (B_q - B_c)^T H (B_q - B_c), and the point's geometric and shear terms.
      Eigen::Matrix<double, 8, 24> B = Eigen::Matrix<double, 8, 24>::Zero();
      strain_operator(pg, ps, tying_, kq[q], c, shear.a_t, shear.d_t, B);
      const Eigen::Matrix<double, 6, 24> dB = B.topRows<6>() - Bc.topRows<6>();
      kp.noalias() += dB.transpose() * (pg.weight * hourglass_stiffness_) * dB;
      add_point_tangent(pg, ps, tying_, hdv, Mat6::Zero(), Q, ks, c, B, false, kp);
    }
  }
  add_strain_operator_transpose(pc, pc, tying_, kc, cc, shear.a_t, shear.d_t, centre_force, Eigen::Vector2d::Zero(), rp);
  if (tangent) {
    // The centre's material and geometric terms (add_point_tangent weighs with the centre's
    // own weight: the forces and stiffness come scaled by its inverse).
    const double inv = 1.0 / pc.weight;
    add_point_tangent(pc, pc, tying_, Vec6(inv * centre_force), Mat6(inv * area_ * d6), Eigen::Vector2d::Zero(), 0.0, cc, Bc, false, kp);
  }

  return dof_results(d, rp, tangent ? &kp : nullptr, false, options_.drilling_factor, area_, residual, tangent);
}

void ShellQ4::enable_sensitivities(int count) {
  for (auto& s : sections_) s.enable_sensitivities(count);
}

namespace {

using SensSlots = Eigen::Matrix<double, 6, material::kSensitivitySlots>;

// One section's part of ShellQ4::sensitivities at strains (e, kappa) and their derivatives ds
// (element frame; Q: element to material frame): the pseudo-resultants (pseudo), or the
// derivatives advanced along ds. With want_resultants, *ds6 receives the resultants'
// derivatives in the element frame; otherwise a linearised section only advances.
SectionStatus section_sensitivities(ShellSection& section, const Eigen::Matrix3d& Q, const Vec3& e, const Vec3& kappa, const SensSlots& ds,
                                    const SensLaw& law, const NarrowLaws* narrow, bool pseudo, bool want_resultants, int count, SensSlots* ds6) {
  Vec3S em, km;
  const Vec3 emv = Q * e, kmv = Q * kappa;
  for (int i = 0; i < 3; ++i) {
    em(i) = material::with_derivatives(emv(i), (Q.row(i) * ds.topRows<3>()));
    km(i) = material::with_derivatives(kmv(i), (Q.row(i) * ds.bottomRows<3>()));
  }
  Vec6S s6m;
  if (pseudo && count + 3 <= material::kSensitivitySlots) {
    const SectionStatus ss = section.pseudo_resultants(law, narrow, emv, kmv, count, &s6m);
    if (!ss.ok) return ss;
  } else if (!pseudo && !want_resultants && section.linearised()) {
    section.advance_sensitivities(em, km);
    return {};
  } else {
    const SectionStatus ss = section.update_sensitivities(law, em, km, &s6m);
    if (!ss.ok) return ss;
  }
  if (!want_resultants) return {};
  SensSlots dsm;
  for (int i = 0; i < 6; ++i) dsm.row(i) = material::derivatives_of(s6m(i));
  ds6->topRows<3>() = Q.transpose() * dsm.topRows<3>();
  ds6->bottomRows<3>() = Q.transpose() * dsm.bottomRows<3>();
  return {};
}

}  // namespace

ElementStatus ShellQ4::sensitivities(const NodeVectors& x, const NodeVectors& d, const SensLaw& law, const SensDofs* du, SensDofs* load, int count,
                                     const NarrowLaws* narrow) {
  using material::kSensitivitySlots;
  const SensDofs dp = du ? director_variable_derivatives(d, *du) : SensDofs::Zero();
  const auto& lp = law.params();
  const material::SensitivityRow dks = options_.shear_factor * h0_ * material::derivatives_of(lp.E / (2.0 * (1.0 + lp.nu)));
  const TransverseShear shear = transverse_shear(x, d);
  if (sections_.size() == 1) return sensitivities_reduced(x, d, law, dp, du == nullptr, load, count, narrow, shear, dks);
  SensDofs rp = SensDofs::Zero();
  for (std::size_t q = 0; q < 4; ++q) {
    const auto p = point_strains(points_[q], centre_, options_.centre_membrane_shear, x, d);
    const PointGeometry& pg = p.pg;
    Eigen::Matrix<double, 8, 24> B = Eigen::Matrix<double, 8, 24>::Zero();
    strain_operator(pg, p.ps, tying_, p.k, p.c, shear.a_t, shear.d_t, B);
    // d (e, kappa) / d p, element frame (zero for the pseudo-loads); coefficient-wise products:
    // Eigen's blocked ones cost more at these sizes.
    const SensSlots ds = du ? SensSlots(B.topRows<6>().lazyProduct(dp)) : SensSlots(SensSlots::Zero());
    SensSlots ds6;
    const SectionStatus ss = section_sensitivities(sections_[q], pg.Q, p.e, p.kappa, ds, law, narrow, du == nullptr, load != nullptr, count, &ds6);
    if (!ss.ok) return point_failure(static_cast<int>(q), ss);
    if (!load) continue;
    const Eigen::Matrix<double, 2, kSensitivitySlots> dQ = shear.gamma[q] * dks;
    rp.noalias() += pg.weight * (B.topRows<6>().transpose().lazyProduct(ds6) + B.bottomRows<2>().transpose().lazyProduct(dQ));
  }
  if (load) *load = director_force_derivatives(d, rp, count);
  return {};
}

ElementStatus ShellQ4::sensitivities_reduced(const NodeVectors& x, const NodeVectors& d, const SensLaw& law, const SensDofs& dp, bool pseudo,
                                             SensDofs* load, int count, const NarrowLaws* narrow, const TransverseShear& shear,
                                             const material::SensitivityRow& dks) {
  using material::kSensitivitySlots;
  // The centre's section, as compute_reduced weighs it: over the whole area.
  const PointGeometry& pc = centre_;
  PointKinematics kc;
  const Vec6 ec = centre_strains(pc, x, d, &kc);
  const double cc[4] = {0.5, 0.5, 0.5, 0.5};
  Eigen::Matrix<double, 8, 24> Bc = Eigen::Matrix<double, 8, 24>::Zero();
  strain_operator(pc, pc, tying_, kc, cc, shear.a_t, shear.d_t, Bc);
  const SensSlots ds = pseudo ? SensSlots(SensSlots::Zero()) : SensSlots(Bc.topRows<6>().lazyProduct(dp));
  SensSlots ds6;
  const SectionStatus ss = section_sensitivities(sections_[0], pc.Q, ec.head<3>(), ec.tail<3>(), ds, law, narrow, pseudo, load != nullptr, count, &ds6);
  if (!ss.ok) return point_failure(0, ss);
  if (!load) return {};  // the hourglass part and the shear keep no state
  // The hourglass stiffness H = fraction (h0 C, h0^3/12 C) moves with the law's elasticity C;
  // the strains' variations dv_q are the nodes' alone. Forces as compute_reduced's:
  // sum_q w_q B_q^T (dH dv_q + dQ_q) + B_c^T (area ds6 - sum_q w_q dH dv_q).
  const auto& C = law.elastic_matrix();
  const double membrane = options_.hourglass_stiffness * h0_, bending = membrane * h0_ * h0_ / 12.0;
  std::array<material::SensitivityRow, 9> dC;  // row-major
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) dC[static_cast<std::size_t>(3 * i + j)] = material::derivatives_of(C(i, j));
  std::array<PointKinematics, 4> kq;
  const std::array<Vec6, 4> dv = strain_variation(x, d, ec, &kq);
  SensSlots centre_force = area_ * ds6;
  SensDofs rp = SensDofs::Zero();
  for (std::size_t q = 0; q < 4; ++q) {
    const PointGeometry& pg = points_[q];
    const PointGeometry& ps = options_.centre_membrane_shear ? centre_ : pg;
    const double c[4] = {0.5 * (1.0 - pg.eta), 0.5 * (1.0 + pg.eta), 0.5 * (1.0 - pg.xi), 0.5 * (1.0 + pg.xi)};
    SensSlots dhdv = SensSlots::Zero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const material::SensitivityRow& dc = dC[static_cast<std::size_t>(3 * i + j)];
        dhdv.row(i) += (membrane * dv[q](j)) * dc;
        dhdv.row(3 + i) += (bending * dv[q](3 + j)) * dc;
      }
    centre_force -= pg.weight * dhdv;
    Eigen::Matrix<double, 8, 24> B = Eigen::Matrix<double, 8, 24>::Zero();
    strain_operator(pg, ps, tying_, kq[q], c, shear.a_t, shear.d_t, B);
    const Eigen::Matrix<double, 2, kSensitivitySlots> dQ = shear.gamma[q] * dks;
    rp.noalias() += pg.weight * (B.topRows<6>().transpose().lazyProduct(dhdv) + B.bottomRows<2>().transpose().lazyProduct(dQ));
  }
  rp.noalias() += Bc.topRows<6>().transpose().lazyProduct(centre_force);
  *load = director_force_derivatives(d, rp, count);
  return {};
}

void ShellQ4::commit() {
  for (auto& s : sections_) s.commit();
}

void ShellQ4::revert() {
  for (auto& s : sections_) s.revert();
}

}  // namespace spifit::element
