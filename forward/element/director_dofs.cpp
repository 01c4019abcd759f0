#include "forward/element/director_dofs.hpp"

#include <array>

namespace spifit::element {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v(2), v(1), v(2), 0.0, -v(0), -v(1), v(0), 0.0;
  return s;
}

// Drilling regularisation: tangent only (it never enters the residual). drilling_factor x the
// mean rotational stiffness (or, with none, the mean translational one x the area) about
// each director.
void add_drilling_stiffness(const NodeVectors& d, double drilling_factor, double area, Mat24& ku) {
  double rot_trace = 0.0, trans_trace = 0.0;
  for (int I = 0; I < 4; ++I) {
    rot_trace += ku.block<3, 3>(6 * I + 3, 6 * I + 3).trace();
    trans_trace += ku.block<3, 3>(6 * I, 6 * I).trace();
  }
  const double k_drill = drilling_factor * (rot_trace > 0.0 ? rot_trace / 12.0 : trans_trace / 12.0 * area);
  for (int I = 0; I < 4; ++I) {
    const Eigen::Vector3d& dI = d[static_cast<std::size_t>(I)];
    ku.block<3, 3>(6 * I + 3, 6 * I + 3) += k_drill * dI * dI.transpose();
  }
}

}  // namespace

void mirror_upper_blocks(Mat24& k) {
  for (int I = 0; I < 4; ++I)
    for (int J = I + 1; J < 4; ++J) k.block<6, 6>(6 * J, 6 * I) = k.block<6, 6>(6 * I, 6 * J).transpose();
}

void director_to_dofs(const NodeVectors& d, const Vec24& rp, const Mat24* kp, Vec24* ru, Mat24* ku, bool symmetric) {
  // dd_I = dpsi_I x d_I = -skew(d_I) dpsi_I.
  *ru = rp;
  for (int I = 0; I < 4; ++I) ru->segment<3>(6 * I + 3) = d[static_cast<std::size_t>(I)].cross(rp.segment<3>(6 * I + 3));
  if (!kp || !ku) return;
  // ku = T^T kp T with T = diag(I, R_1, I, R_2, ...), R_I = -skew(d_I): done on the 3 x 3 blocks
  // (the dense 24 x 24 triple product cost about as much as the rest of the element).
  std::array<Eigen::Matrix3d, 4> R;
  for (int I = 0; I < 4; ++I) R[static_cast<std::size_t>(I)] = -skew(d[static_cast<std::size_t>(I)]);
  for (int I = 0; I < 4; ++I) {
    const Eigen::Matrix3d& RI = R[static_cast<std::size_t>(I)];
    for (int J = symmetric ? I : 0; J < 4; ++J) {
      const Eigen::Matrix3d& RJ = R[static_cast<std::size_t>(J)];
      const int ti = 6 * I, ri = 6 * I + 3, tj = 6 * J, rj = 6 * J + 3;
      ku->block<3, 3>(ti, tj) = kp->block<3, 3>(ti, tj);
      ku->block<3, 3>(ti, rj).noalias() = kp->block<3, 3>(ti, rj) * RJ;
      ku->block<3, 3>(ri, tj).noalias() = RI.transpose() * kp->block<3, 3>(ri, tj);
      ku->block<3, 3>(ri, rj).noalias() = RI.transpose() * (kp->block<3, 3>(ri, rj) * RJ);
    }
  }
  if (symmetric) mirror_upper_blocks(*ku);
  for (int I = 0; I < 4; ++I) {
    // Rotational geometric term, projected on the plane normal to the director (the drilling
    // rotation does not move d): P (d r^T - (d.r) I) P = -(d.r) P with P = I - d d^T.
    const Eigen::Vector3d& dI = d[static_cast<std::size_t>(I)];
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - dI * dI.transpose();
    ku->block<3, 3>(6 * I + 3, 6 * I + 3) += -dI.dot(rp.segment<3>(6 * I + 3)) * P;
  }
}

SensDofs director_variable_derivatives(const NodeVectors& d, const SensDofs& du) {
  SensDofs dp = du;
  for (int I = 0; I < 4; ++I)
    for (int k = 0; k < material::kSensitivitySlots; ++k)
      dp.block<3, 1>(6 * I + 3, k) = Eigen::Vector3d(du.block<3, 1>(6 * I + 3, k)).cross(d[static_cast<std::size_t>(I)]);
  return dp;
}

SensDofs director_force_derivatives(const NodeVectors& d, const SensDofs& rp, int count) {
  SensDofs out = SensDofs::Zero();
  for (int k = 0; k < count; ++k) {
    Vec24 ru;
    director_to_dofs(d, Vec24(rp.col(k)), nullptr, &ru, nullptr);
    out.col(k) = ru;
  }
  return out;
}

ElementStatus dof_results(const NodeVectors& d, const Vec24& rp, const Mat24* kp, bool symmetric, double drilling_factor, double area,
                          Vec24* residual, Mat24* tangent) {
  Vec24 ru;
  Mat24 ku;
  director_to_dofs(d, rp, kp, &ru, kp ? &ku : nullptr, symmetric);
  ElementStatus status;
  if (!ru.allFinite()) {
    status.ok = false;
    status.reason = "non-finite element forces";
    status.suggested_scale = 0.25;
    return status;
  }
  if (residual) *residual = ru;
  if (kp && tangent) {
    add_drilling_stiffness(d, drilling_factor, area, ku);
    *tangent = ku;
  }
  return status;
}

}  // namespace spifit::element
