#pragma once
// The one-point brick at large strain (docs/design/numerics-solid.md, "Large strain"): the
// thesis's BWD3D kind of element (§3.1.2), 8 nodes, one integration point, physical hourglass
// stabilisation, any 3D law.
//
// Kinematics (Total Lagrangian, reference coordinates in the element's material frame):
//   F = A (I + H) with A the material axes, b the uniform gradient of the reference shape in the
//   material frame (hex8_stiffness.hpp) and H = A^T sum_I u_I b_I^T the displacement gradient
//   (u = x - X), E = (F^T F - I) / 2 = (H + H^T + H^T H) / 2 in the material frame, so that the
//   law's axes turn with the material. From the displacements, an undeformed element has no
//   stress at all; from the positions (F = sum_I x_I b_I^T) round-off left 2e-9 N of residual in
//   an unloaded cone pie 20 mm from the origin, which no relative force test can pass;
//   the centre's stress comes from a SolidPoint (log strain, 3D return mapping):
//   f_I = V0 F S b_I.
// Hourglass: the amplitudes q_a = sum_I gamma_aI x_I of the current positions (evaluated as
// sum_I gamma_aI u_I, the reference positions being a linear field) vanish for every
// linear field, rigid motions included, and turn with the element; pulled back,
// Q_a = F^T q_a, they are objective and equal the small-strain amplitudes at F = I. Q is
// bilinear in the positions, so forces and tangent are exact in closed form. The hourglass
// forces g conjugate to Q grow by K_q(D) (Q - Q_n) over an increment, with K_q the
// incompatible-modes stiffness of unit hourglass amplitudes (hex_hourglass_stiffness) for the
// centre's consistent tangent D at the start of the increment, times a scale: elastic
// while the element is, and as soft as the material once it flows. An elastic stabilisation
// (HourglassOptions::elastic) resists plastic bending of a layer elastically: a strip bent to 17
// times its yield curvature carried 4.1 (two layers) to 1.4 (eight layers) times its plastic
// limit moment with it, against 1.45 to 1.04 on the tangent (docs/design/numerics-solid.md).
#include "forward/element/hex8_stiffness.hpp"
#include "forward/element/solid_element.hpp"
#include "forward/element/solid_point.hpp"

#include <Eigen/Core>

#include <vector>

namespace spifit::element {

// The hourglass stabilisation: the factor on the incompatible-modes stiffness, and the modulus it
// is built on (the centre's consistent tangent, or the elastic matrix throughout, as an
// elastic anti-hourglass treatment has it).
struct HourglassOptions {
  double scale = 1.0;
  bool elastic = false;
};

using BrickStatus = PointStatus;

class Brick8 final : public SolidElement {
 public:
  using Law = SolidPoint::Law;

  // X: reference corners (VTK order); axes: orthonormal material axes as columns (rolling,
  // transverse, normal) in global coordinates. Throws std::invalid_argument for an element whose
  // Jacobian is not positive, or a hourglass scale that is not finite and >= 0.
  Brick8(const HexCorners& X, const Eigen::Matrix3d& axes, const Law& law, const HourglassOptions& hourglass = {});

  // Internal forces (24: ux uy uz per corner) and their tangent at the current corners x; f, K
  // may be null. The centre's trial state is what commit() keeps.
  BrickStatus evaluate(const HexCorners& x, HexVector* f, HexMatrix* K) override;
  void commit() override;
  void revert() override;

  // Direct differentiation (SolidElement; docs/design/sensitivities.md, "Solids"): the committed
  // state's derivatives are the centre's, the hourglass amplitudes' and forces', the
  // stabilisation's stiffness's and the thickness's.
  void enable_sensitivities(const SolidSensitivityLaw& law, int count) override;
  BrickStatus sensitivities(const HexCorners& x, const SolidSensitivityLaw& law, const HexSensitivities* du, HexSensitivities* load) override;
  bool tangent_was_exact() const override { return point_.tangent_was_exact(); }
  void set_exact_tangents(bool exact) override { point_.set_exact_tangents(exact); }
  const material::SensitivityRow& thickness_ratio_sensitivity() const override { return dthickness_; }
  void save_sensitivities(io::BinaryWriter& w, int count) const override;
  void load_sensitivities(io::BinaryReader& r, int count) override;

  // F (global current <- material-frame reference) at the corners x.
  Eigen::Matrix3d deformation_gradient(const HexCorners& x) const;
  // H = A^T dU/dX_m, the displacement gradient in the material frame (F = A (I + H)).
  Eigen::Matrix3d displacement_gradient(const HexCorners& x) const;
  const SolidPoint& point() const { return point_; }
  const Eigen::Matrix3d& axes() const { return axes_; }
  double reference_volume() const { return volume0_; }
  // The work of the hourglass forces up to the committed state [N mm] (trapezoidal sum).
  double hourglass_energy() const { return hourglass_energy_; }
  // Committed hourglass amplitudes Q (pulled back, material frame) and the forces g conjugate
  // to them, in hex_hourglass_operator's order (3 a + i: mode a, component i).
  const Eigen::Matrix<double, 12, 1>& hourglass_amplitudes() const { return q_; }
  const Eigen::Matrix<double, 12, 1>& hourglass_forces() const { return g_; }
  // Extent along the material normal of the committed state relative to the reference one,
  // h / h0 = 1 / |F^-T N| (Nanson), N the third material axis.
  double thickness_ratio() const override { return thickness_ratio_; }
  // The centre's stored energy plus the hourglass forces' work; the centre's plastic work.
  double elastic_energy() const override { return volume0_ * point_.elastic_energy_density() + hourglass_energy_; }
  double plastic_work() const override { return volume0_ * point_.plastic_work_density(); }
  double max_eqps() const override { return point_.committed().eqps; }
  Voigt6 mean_stress() const override { return point_.committed().stress; }

  void save_state(io::BinaryWriter& w) const override;
  void load_state(io::BinaryReader& r) override;

 private:
  Eigen::Matrix3d axes_;
  Eigen::Matrix<double, 3, 8> b_;      // uniform gradient over material-frame reference coordinates
  Eigen::Matrix<double, 4, 8> gamma_;  // hourglass vectors
  HexCorners reference_;                // corners in the material frame
  HexCorners corners_;                  // corners in global coordinates (X)
  HourglassOptions hourglass_;
  Eigen::Matrix<double, 12, 12> kq_elastic_, kq_;  // K_q of the elastic matrix, of the committed tangent
  Eigen::Matrix<double, 12, 1> q_ = Eigen::Matrix<double, 12, 1>::Zero(), q_trial_ = Eigen::Matrix<double, 12, 1>::Zero();  // Q
  Eigen::Matrix<double, 12, 1> g_ = Eigen::Matrix<double, 12, 1>::Zero(), g_trial_ = Eigen::Matrix<double, 12, 1>::Zero();  // hourglass forces
  double volume0_ = 0.0;
  void update_hourglass_stiffness();
  // The parts of evaluate() that sensitivities() shares: E in the material frame, the hourglass
  // vectors q of the corners, B = dE/dx and M = dQ/dx.
  static Voigt6 green_strain(const Eigen::Matrix3d& H);
  Eigen::Matrix<double, 3, 4> hourglass_vectors(const HexCorners& x) const;
  Eigen::Matrix<double, 6, 24> strain_matrix(const Eigen::Matrix3d& F) const;
  Eigen::Matrix<double, 12, 24> amplitude_matrix(const Eigen::Matrix3d& F, const Eigen::Matrix<double, 3, 4>& q) const;
  // Direct differentiation: dK_q of the committed tangent, and its derivatives.
  void update_hourglass_stiffness_derivatives();
  using Mat12 = Eigen::Matrix<double, 12, 12>;
  using Sens12 = Eigen::Matrix<double, 12, material::kSensitivitySlots>;
  int sensitivity_count_ = 0;
  std::vector<Mat12> dkq_elastic_, dkq_;  // per parameter
  Sens12 dq_ = Sens12::Zero(), dq_trial_ = Sens12::Zero(), dg_ = Sens12::Zero(), dg_trial_ = Sens12::Zero();
  material::SensitivityRow dthickness_ = material::SensitivityRow::Zero(), dthickness_trial_ = material::SensitivityRow::Zero();
  SolidPoint point_;
  double hourglass_energy_ = 0.0, hourglass_energy_trial_ = 0.0;
  double thickness_ratio_ = 1.0, thickness_ratio_trial_ = 1.0;
};

}  // namespace spifit::element
