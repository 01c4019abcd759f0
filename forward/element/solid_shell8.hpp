#pragma once
// The solid-shell: an 8-node hexahedron with one element through the sheet's thickness and
// several integration points along it, any 3D law with no plane-stress assumption
// (docs/design/numerics-solid.md, "Solid-shell"). The remedy the thesis names for what neither
// its shell nor its one-point brick reproduces on the 70 degree cone (§9.2.2).
//
// Corners 0-3 are the bottom face, 4-7 the top face (VTK order, zeta the thickness direction).
// Total Lagrangian with the Green-Lagrange strain E, its components taken in the convective
// frame, e_ij = (g_i . g_j - G_i . G_j) / 2 (engineering shears doubled), and turned into the
// element's material frame at each point. The thickness strain e_33 is the compatible one at
// each point: the assumed natural strain that removes curvature thickness locking of curved
// reference shells (e_33 tied at the corner columns, Betsch & Stein 1995) is left out, as spifit's
// reference sheets are flat; with it the column lengths replace the element's mean column, and
// under the tool of the line test, where the columns of one element turn by up to 0.7 rad, the
// elements lost up to 15 % of their volume and the sheet thinned 13 % more than with bricks.
// The locking remedies:
//   * transverse shear (assumed natural strain, Dvorkin & Bathe 1986): e_13 sampled at the edge
//     midpoints eta = -1, +1 and e_23 at xi = -1, +1 of the point's zeta level, interpolated
//     linearly;
//   * thickness (Poisson) locking (enhanced assumed strain, Buechter, Ramm & Roehl 1994): e_33
//     gains zeta (a1 + a2 xi + a3 eta + a4 xi eta), so the thickness strain of every in-plane
//     point varies linearly through the thickness, as a Poisson effect in bending and plastic
//     incompressibility need. The enhanced field is taken at the centre and scaled by
//     det J0 / det J (Simo & Rifai 1990), so it does no work on a constant stress: the patch
//     test holds on distorted elements;
//   * volumetric locking of a membrane that flows plastically (mean dilatation, Nagtegaal, Parks
//     & Rice 1974, here in log-strain space): the four in-plane points of a thickness level share
//     the level's mean volumetric log strain (and so its mean pressure), each keeping its own
//     deviator. Without it, four incompressible points per element against about one column
//     stretch of the nodes per element lock (the indent of §7.1 carried 45 % more force than the
//     shell's, with e_33 tied at the corner columns); freeing each point's thickness strain by enhanced modes instead (xi, eta, xi eta)
//     leaves the columns' stretches a zero-energy checkerboard.
// In-plane 2 x 2 Gauss points (no hourglass modes) times the thickness rule's points. The four
// enhanced parameters are condensed out per element: every evaluation solves for them by Newton's
// method from the previous evaluation's values plus a linear predictor, to a change below 1e-8;
// the residual left is removed from the forces to first order, and the tangent is the condensed
// one. After a commit or a revert the previous values are the committed ones, so a run restarted
// from a checkpoint evaluates as the uninterrupted one.
// Direct differentiation (docs/design/sensitivities.md, "Solids"): the enhanced parameters carry
// no history (every evaluation solves for them afresh), so their derivatives follow from the
// condensed equations alone, d alpha = -K_aa^-1 (K_au du + d r_a / d p), and the pseudo-load of
// the corners is the condensed one, d f_u / d p - K_ua K_aa^-1 d r_a / d p (both at fixed corners
// and enhanced parameters, through the points' committed derivatives).
#include "forward/element/hex8_stiffness.hpp"
#include "forward/element/solid_element.hpp"
#include "forward/element/solid_point.hpp"
#include "forward/element/thickness_rule.hpp"

#include <Eigen/Core>

#include <vector>

namespace spifit::element {

class SolidShell8 final : public SolidElement {
 public:
  using Law = SolidPoint::Law;
  static constexpr int kEnhanced = 4;
  using EnhancedVector = Eigen::Matrix<double, kEnhanced, 1>;
  // The enhanced parameters' Newton iteration stops at a change below this.
  static constexpr double kDefaultEnhancedTolerance = 1e-8;

  // X: reference corners; axes: orthonormal material axes as columns (rolling, transverse,
  // normal). Throws std::invalid_argument for a Jacobian that is not positive at a point or axes
  // that are not orthonormal. enhanced_tolerance: the enhanced parameters' Newton iteration
  // stops at a change below it (the committed points' states carry an error of that order).
  SolidShell8(const HexCorners& X, const Eigen::Matrix3d& axes, const Law& law, const ThicknessRule& rule,
              double enhanced_tolerance = kDefaultEnhancedTolerance);

  // Internal forces (24) and the condensed tangent at the corners x; K may be null.
  PointStatus evaluate(const HexCorners& x, HexVector* f, HexMatrix* K) override;
  void commit() override;
  void revert() override;

  int num_points() const { return static_cast<int>(points_.size()); }
  const SolidPoint& point(int p) const { return points_[static_cast<std::size_t>(p)]; }
  // Reference volume that point p stands for (Gauss weights times det J).
  double point_volume(int p) const { return geometry_[static_cast<std::size_t>(p)].weight; }
  double reference_volume() const { return volume0_; }
  const Eigen::Matrix3d& axes() const { return axes_; }
  // Committed enhanced parameters and the Newton iterations on them in the last evaluation.
  const EnhancedVector& enhanced() const { return alpha_; }
  int enhanced_iterations() const { return last_iterations_; }
  // Committed thickness over the reference one at the element's centre, |g_3| / |G_3|.
  double thickness_ratio() const override { return thickness_ratio_; }
  double elastic_energy() const override;
  double plastic_work() const override;
  double max_eqps() const override;
  Voigt6 mean_stress() const override;

  void save_state(io::BinaryWriter& w) const override;
  void load_state(io::BinaryReader& r) override;

  // Direct differentiation (SolidElement): the points' derivatives and the thickness's.
  void enable_sensitivities(const SolidSensitivityLaw& law, int count) override;
  PointStatus sensitivities(const HexCorners& x, const SolidSensitivityLaw& law, const HexSensitivities* du, HexSensitivities* load) override;
  const material::SensitivityRow& thickness_ratio_sensitivity() const override { return dthickness_; }
  bool tangent_was_exact() const override;
  // With exact tangents an evaluation at the converged iterate keeps its enhanced parameters and
  // their predictor (one pass, no Newton step on them), so that the next increment starts as
  // Newton's would.
  void set_exact_tangents(bool exact) override;
  void save_sensitivities(io::BinaryWriter& w, int count) const override;
  void load_sensitivities(io::BinaryReader& r, int count) override;

 private:
  struct PointGeometry {
    Eigen::Vector3d s;   // parent coordinates (xi, eta, zeta)
    int level = 0;       // index of the zeta level
    Voigt6x6 T;          // Voigt transformation, convective (engineering) -> material frame
    Eigen::Matrix<double, 6, kEnhanced> Gamma;  // enhanced strain per parameter (material frame)
    double weight = 0.0;
  };
  struct Sums;
  // Forces, enhanced residual and the blocks of the tangent in (x, alpha) at the corners x and
  // the enhanced parameters alpha (the block in x only with with_kuu: a residual alone needs the
  // blocks in alpha for the condensation, not that one); the points' trial states follow.
  void accumulate(const Eigen::Matrix<double, 3, 8>& x, const EnhancedVector& alpha, bool with_kuu, Sums* sums, PointStatus* status);

  Eigen::Matrix3d axes_;
  Eigen::Matrix<double, 3, 8> X_;  // reference corners in the material frame
  std::vector<double> zeta_;       // thickness levels
  // The law's consistent tangent is symmetric (no kinematic hardening): the tangent's blocks are
  // formed from one triangle, d ra / d x as the transpose of d f / d alpha.
  bool symmetric_ = true;
  std::vector<PointGeometry> geometry_;
  std::vector<SolidPoint> points_;
  double volume0_ = 0.0;
  // Reference values of the sampled shears, per zeta level: e13 at eta = -1, +1, e23 at
  // xi = -1, +1 (G_i . G_j).
  std::vector<Eigen::Vector4d> shear0_;
  double g3_norm0_ = 0.0;
  double enhanced_tolerance_ = kDefaultEnhancedTolerance;
  // Committed / trial: enhanced parameters, the corners they belong to, and their derivative
  // d alpha / d x there (the predictor of the next evaluation).
  EnhancedVector alpha_ = EnhancedVector::Zero(), alpha_trial_ = EnhancedVector::Zero();
  Eigen::Matrix<double, 3, 8> x_committed_, x_trial_;
  Eigen::Matrix<double, kEnhanced, 24> dalpha_ = Eigen::Matrix<double, kEnhanced, 24>::Zero(), dalpha_trial_ = Eigen::Matrix<double, kEnhanced, 24>::Zero();
  double thickness_ratio_ = 1.0, thickness_ratio_trial_ = 1.0;
  int last_iterations_ = 0;
  // Direct differentiation: the last evaluation's K_aa^-1, K_ua and -K_aa^-1 K_au (with the
  // tangents it had), the pseudo-load's d r_a / d p, and the thickness ratio's derivatives.
  int sensitivity_count_ = 0;
  bool exact_tangents_ = false;
  Eigen::Matrix<double, kEnhanced, kEnhanced> kaa_inverse_ = Eigen::Matrix<double, kEnhanced, kEnhanced>::Zero();
  Eigen::Matrix<double, 24, kEnhanced> kua_ = Eigen::Matrix<double, 24, kEnhanced>::Zero();
  Eigen::Matrix<double, kEnhanced, 24> dalpha_du_ = Eigen::Matrix<double, kEnhanced, 24>::Zero();
  Eigen::Matrix<double, kEnhanced, material::kSensitivitySlots> dra_ = Eigen::Matrix<double, kEnhanced, material::kSensitivitySlots>::Zero();
  material::SensitivityRow dthickness_ = material::SensitivityRow::Zero(), dthickness_trial_ = material::SensitivityRow::Zero();
};

}  // namespace spifit::element
