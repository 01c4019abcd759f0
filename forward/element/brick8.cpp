#include "forward/element/brick8.hpp"

#include "forward/io/binary_archive.hpp"

#include <Eigen/LU>

#include <cmath>
#include <stdexcept>
#include <string>

namespace spifit::element {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

Brick8::Brick8(const HexCorners& X, const Eigen::Matrix3d& axes, const Law& law, const HourglassOptions& hourglass)
    : axes_(axes), corners_(X), hourglass_(hourglass), point_(law) {
  if (!(std::isfinite(hourglass.scale) && hourglass.scale >= 0.0))
    throw std::invalid_argument("hourglass scale must be finite and >= 0, got " + std::to_string(hourglass.scale));
  if (!((axes.transpose() * axes - Mat3::Identity()).cwiseAbs().maxCoeff() < 1e-10 && axes.determinant() > 0.0))
    throw std::invalid_argument("material axes of a brick must be orthonormal and right-handed");
  HexCorners& Xm = reference_;
  for (std::size_t I = 0; I < 8; ++I) Xm[I] = axes.transpose() * X[I];
  const HexUniformGradient g = hex_uniform_gradient(Xm);  // throws for a non-positive Jacobian
  b_ = g.b;
  volume0_ = g.volume;
  const Eigen::Matrix<double, 12, 24> G = hex_hourglass_operator(Xm, g);
  for (int a = 0; a < 4; ++a)
    for (int I = 0; I < 8; ++I) gamma_(a, I) = G(3 * a, 3 * I);
  kq_elastic_ = kq_ = hourglass.scale * hex_hourglass_stiffness(Xm, law.elastic_matrix());
}

// K_q for the committed consistent tangent: rebuilt only where that tangent is not the elastic
// matrix (the elements that flowed in the last increment).
void Brick8::update_hourglass_stiffness() {
  const Voigt6x6& D = point_.consistent_tangent();
  if (hourglass_.elastic || D == point_.committed_law_elastic_matrix()) kq_ = kq_elastic_;
  else kq_ = hourglass_.scale * hex_hourglass_stiffness(reference_, D);
}

Mat3 Brick8::displacement_gradient(const HexCorners& x) const {
  Mat3 G = Mat3::Zero();
  for (std::size_t I = 0; I < 8; ++I) G += (x[I] - corners_[I]) * b_.col(static_cast<int>(I)).transpose();
  return axes_.transpose() * G;
}

Mat3 Brick8::deformation_gradient(const HexCorners& x) const { return axes_ * (Mat3::Identity() + displacement_gradient(x)); }

Voigt6 Brick8::green_strain(const Mat3& H) {
  const Mat3 C1 = H + H.transpose() + H.transpose() * H;  // C - I
  Voigt6 green;
  green << 0.5 * C1(0, 0), 0.5 * C1(1, 1), 0.5 * C1(2, 2), C1(0, 1), C1(0, 2), C1(1, 2);
  return green;
}

Eigen::Matrix<double, 3, 4> Brick8::hourglass_vectors(const HexCorners& x) const {
  Eigen::Matrix<double, 3, 8> us;
  for (std::size_t I = 0; I < 8; ++I) us.col(static_cast<int>(I)) = x[I] - corners_[I];
  return us * gamma_.transpose();
}

// B_J (6 x 3): d E (Voigt, engineering shears) / d x_J.
Eigen::Matrix<double, 6, 24> Brick8::strain_matrix(const Mat3& F) const {
  Eigen::Matrix<double, 6, 24> B;
  for (int J = 0; J < 8; ++J) {
    const Vec3 bj = b_.col(J);
    auto blk = B.block<6, 3>(0, 3 * J);
    blk.row(0) = bj(0) * F.col(0).transpose();
    blk.row(1) = bj(1) * F.col(1).transpose();
    blk.row(2) = bj(2) * F.col(2).transpose();
    blk.row(3) = bj(0) * F.col(1).transpose() + bj(1) * F.col(0).transpose();
    blk.row(4) = bj(0) * F.col(2).transpose() + bj(2) * F.col(0).transpose();
    blk.row(5) = bj(1) * F.col(2).transpose() + bj(2) * F.col(1).transpose();
  }
  return B;
}

// M (12 x 24): d Q / d x, block (a, J) = b_J q_a^T + gamma_aJ F^T.
Eigen::Matrix<double, 12, 24> Brick8::amplitude_matrix(const Mat3& F, const Eigen::Matrix<double, 3, 4>& q) const {
  Eigen::Matrix<double, 12, 24> M;
  for (int a = 0; a < 4; ++a)
    for (int J = 0; J < 8; ++J)
      M.block<3, 3>(3 * a, 3 * J) = b_.col(J) * q.col(a).transpose() + gamma_(a, J) * F.transpose();
  return M;
}

BrickStatus Brick8::evaluate(const HexCorners& x, HexVector* f, HexMatrix* K) {
  BrickStatus status;
  const Mat3 H = displacement_gradient(x);
  const Mat3 F = axes_ * (Mat3::Identity() + H);
  const double detF = F.determinant();
  if (!(detF > 0.0)) {
    status.ok = false;
    status.reason = std::isfinite(detF) ? "element turned inside out (det F = " + std::to_string(detF) + ")" : "non-finite positions";
    status.suggested_scale = 0.25;
    return status;
  }
  const Voigt6 green = green_strain(H);
  Voigt6 S;
  Voigt6x6 D;
  const PointStatus ps = point_.update(green, &S, K ? &D : nullptr);
  if (!ps.ok) {
    status.ok = false;
    status.reason = ps.reason;
    status.suggested_scale = ps.suggested_scale;
    return status;
  }
  thickness_ratio_trial_ = 1.0 / F.inverse().transpose().col(2).norm();

  // Hourglass amplitudes and their pull-back.
  const Eigen::Matrix<double, 3, 4> q = hourglass_vectors(x);
  Eigen::Matrix<double, 12, 1> Q;
  for (int a = 0; a < 4; ++a) Q.segment<3>(3 * a) = F.transpose() * q.col(a);
  const Eigen::Matrix<double, 12, 1> gq = g_ + kq_ * (Q - q_);
  q_trial_ = Q;
  g_trial_ = gq;
  hourglass_energy_trial_ = hourglass_energy_ + 0.5 * (g_ + gq).dot(Q - q_);

  Mat3 St;
  St << S(0), S(3), S(4), S(3), S(1), S(5), S(4), S(5), S(2);
  const Eigen::Matrix<double, 6, 24> B = strain_matrix(F);
  const Eigen::Matrix<double, 12, 24> M = amplitude_matrix(F, q);

  if (f) *f = volume0_ * B.transpose() * S + M.transpose() * gq;
  if (K) {
    *K = volume0_ * B.transpose() * D * B + M.transpose() * kq_ * M;
    // Geometric parts: V0 (b_J . S b_K) I from the centre, and
    // sum_a [gamma_aK (b_J . g_a) + gamma_aJ (b_K . g_a)] I from the pull-back of the amplitudes.
    const Eigen::Matrix<double, 8, 8> centre = volume0_ * b_.transpose() * St * b_;
    Eigen::Matrix<double, 8, 4> bg;  // b_J . g_a
    for (int a = 0; a < 4; ++a) bg.col(a) = b_.transpose() * gq.segment<3>(3 * a);
    const Eigen::Matrix<double, 8, 8> hg = bg * gamma_;  // (J, K): sum_a (b_J . g_a) gamma_aK
    for (int J = 0; J < 8; ++J)
      for (int Kn = 0; Kn < 8; ++Kn) {
        const double s = centre(J, Kn) + hg(J, Kn) + hg(Kn, J);
        for (int i = 0; i < 3; ++i) (*K)(3 * J + i, 3 * Kn + i) += s;
      }
  }
  return status;
}

void Brick8::enable_sensitivities(const SolidSensitivityLaw& law, int count) {
  if (count < 1 || count > material::kSensitivitySlots) throw std::invalid_argument("brick sensitivities: " + std::to_string(count) + " parameters");
  sensitivity_count_ = count;
  point_.enable_sensitivities();
  // K_q of the elastic matrix moves with E and nu.
  const Voigt6x6& Ce = point_.committed_law_elastic_matrix();
  dkq_elastic_.assign(static_cast<std::size_t>(count), Mat12::Zero());
  for (int k = 0; k < count; ++k) {
    Voigt6x6 dCe;
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i) dCe(i, j) = law.full.elastic_matrix()(i, j).v(k);
    if (dCe.cwiseAbs().maxCoeff() > 0.0) dkq_elastic_[static_cast<std::size_t>(k)] = hourglass_.scale * hex_hourglass_stiffness_derivative(reference_, Ce, dCe);
  }
  dq_ = dq_trial_ = dg_ = dg_trial_ = Sens12::Zero();
  dthickness_ = dthickness_trial_ = material::SensitivityRow::Zero();
  update_hourglass_stiffness_derivatives();
}

void Brick8::update_hourglass_stiffness_derivatives() {
  if (sensitivity_count_ == 0) return;
  const Voigt6x6& D = point_.consistent_tangent();
  if (hourglass_.elastic || D == point_.committed_law_elastic_matrix()) {
    dkq_ = dkq_elastic_;
    return;
  }
  dkq_.assign(static_cast<std::size_t>(sensitivity_count_), Mat12::Zero());
  const auto& dD = point_.committed_derivatives().tangent;
  std::vector<Voigt6x6> directions;
  std::vector<int> slots;
  for (int k = 0; k < sensitivity_count_; ++k) {
    const Voigt6x6 dDk = Eigen::Map<const Voigt6x6>(dD.col(k).data());
    if (dDk.cwiseAbs().maxCoeff() > 0.0) {
      directions.push_back(dDk);
      slots.push_back(k);
    }
  }
  if (directions.empty()) return;
  const std::vector<Mat12> d = hex_hourglass_stiffness_derivatives(reference_, D, directions);
  for (std::size_t i = 0; i < slots.size(); ++i) dkq_[static_cast<std::size_t>(slots[i])] = hourglass_.scale * d[i];
}

BrickStatus Brick8::sensitivities(const HexCorners& x, const SolidSensitivityLaw& law, const HexSensitivities* du, HexSensitivities* load) {
  if (sensitivity_count_ == 0) throw std::logic_error("Brick8::sensitivities before enable_sensitivities");
  const int n = sensitivity_count_;
  const Mat3 H = displacement_gradient(x);
  const Mat3 F = axes_ * (Mat3::Identity() + H);
  const LogStrain3 ls = log_strain_3d(green_strain(H));
  const Eigen::Matrix<double, 3, 4> q = hourglass_vectors(x);
  Eigen::Matrix<double, 12, 1> Q;
  for (int a = 0; a < 4; ++a) Q.segment<3>(3 * a) = F.transpose() * q.col(a);
  const Eigen::Matrix<double, 6, 24> B = strain_matrix(F);
  const Eigen::Matrix<double, 12, 24> M = amplitude_matrix(F, q);
  SensColumns6 deps = SensColumns6::Zero();
  if (du) deps = ls.first * (B * *du);
  Voigt6S T;
  const PointStatus ps = point_.sensitivities(law, ls.value, du ? &deps : nullptr, &T);
  if (!ps.ok) return ps;
  const Eigen::Matrix<double, 12, 1> dQ0 = Q - q_;
  if (load) {
    // At fixed corners: S = (d eps / dE)^T T moves with T alone, the hourglass forces
    // g_n + K_q (Q - Q_n) with the committed g_n, K_q and Q_n.
    SensColumns6 dT;
    for (int i = 0; i < 6; ++i) dT.row(i) = material::derivatives_of(T(i));
    const SensColumns6 dS = ls.first.transpose() * dT;
    Sens12 dgq = dg_ - kq_ * dq_;
    for (int k = 0; k < n; ++k) dgq.col(k) += dkq_[static_cast<std::size_t>(k)] * dQ0;
    *load = volume0_ * B.transpose() * dS + M.transpose() * dgq;
    load->rightCols(material::kSensitivitySlots - n).setZero();
  }
  if (du) {
    const Sens12 dQ = M * *du;
    dq_trial_ = dQ;
    dg_trial_ = dg_ + kq_ * (dQ - dq_);
    for (int k = 0; k < n; ++k) dg_trial_.col(k) += dkq_[static_cast<std::size_t>(k)] * dQ0;
    // h / h0 = 1 / |w|, w = F^-T N: dw = -F^-T dF^T w with dF = sum_I du_I b_I^T.
    const Mat3 Finv_t = F.inverse().transpose();
    const Vec3 w = Finv_t.col(2);
    const double r = 1.0 / w.norm();
    dthickness_trial_.setZero();
    for (int k = 0; k < n; ++k) {
      Mat3 dF = Mat3::Zero();
      for (int I = 0; I < 8; ++I) dF += du->block<3, 1>(3 * I, k) * b_.col(I).transpose();
      const Vec3 dw = -Finv_t * (dF.transpose() * w);
      dthickness_trial_(k) = -r * r * r * w.dot(dw);
    }
  }
  return ps;
}

void Brick8::commit() {
  point_.commit();
  hourglass_energy_ = hourglass_energy_trial_;
  thickness_ratio_ = thickness_ratio_trial_;
  q_ = q_trial_;
  g_ = g_trial_;
  update_hourglass_stiffness();
  if (sensitivity_count_ > 0) {
    dq_ = dq_trial_;
    dg_ = dg_trial_;
    dthickness_ = dthickness_trial_;
    update_hourglass_stiffness_derivatives();
  }
}

void Brick8::revert() {
  point_.revert();
  hourglass_energy_trial_ = hourglass_energy_;
  thickness_ratio_trial_ = thickness_ratio_;
  q_trial_ = q_;
  g_trial_ = g_;
  dq_trial_ = dq_;
  dg_trial_ = dg_;
  dthickness_trial_ = dthickness_;
}

void Brick8::save_state(io::BinaryWriter& w) const {
  point_.save_state(w);
  w.f64(hourglass_energy_);
  w.f64(thickness_ratio_);
  w.vector(q_);
  w.vector(g_);
}

void Brick8::load_state(io::BinaryReader& r) {
  point_.load_state(r);
  hourglass_energy_ = hourglass_energy_trial_ = r.f64();
  thickness_ratio_ = thickness_ratio_trial_ = r.f64();
  const Eigen::VectorXd q = r.vector(), g = r.vector();
  if (q.size() != 12 || g.size() != 12) throw io::ArchiveError("brick: hourglass amplitudes and forces need 12 components each");
  q_ = q_trial_ = q;
  g_ = g_trial_ = g;
  update_hourglass_stiffness();
}

}  // namespace spifit::element

namespace spifit::element {

void Brick8::save_sensitivities(io::BinaryWriter& w, int count) const {
  point_.save_sensitivities(w, count);
  save_columns(w, dq_, count);
  save_columns(w, dg_, count);
  save_columns(w, dthickness_, count);
}

void Brick8::load_sensitivities(io::BinaryReader& r, int count) {
  if (count != sensitivity_count_) throw std::logic_error("Brick8::load_sensitivities: another parameter count than enabled");
  point_.load_sensitivities(r, count);
  load_columns(r, "brick hourglass amplitude", count, &dq_);
  load_columns(r, "brick hourglass force", count, &dg_);
  load_columns(r, "brick thickness", count, &dthickness_);
  dq_trial_ = dq_;
  dg_trial_ = dg_;
  dthickness_trial_ = dthickness_;
  update_hourglass_stiffness_derivatives();
}

}  // namespace spifit::element
