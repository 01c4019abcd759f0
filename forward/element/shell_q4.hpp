#pragma once
// ShellQ4: 4-node elastoplastic shell for large rotations and large membrane strains
// (theory and references in docs/design/numerics-shell.md).
//
//  * Degenerated-solid kinematics with a unit director per node: the point (xi, eta, zeta)
//    sits at x = sum N_I (x_I + zeta h/2 d_I). Total Lagrangian: strains are measured from
//    the initial configuration in a material frame attached to it (e1 = projection of the
//    rolling direction on the mid-surface), so the stress update is objective and the
//    orthotropy axes follow the material.
//  * Membrane e and bending kappa: Green-Lagrange strains linear in the thickness
//    coordinate, computed in an element frame (e1 along the xi direction at the centre,
//    projected on the tangent plane) and rotated into the material frame for the layers;
//    each of the 2x2 Gauss points carries a ShellSection (1..11 layers,
//    logarithmic-strain plasticity in plane stress).
//    With hourglass_stiffness > 0 the centre alone carries one, and the strains' variation
//    over the element gets an elastic stiffness (docs/design/explicit.md, "One-point element").
//  * Transverse shear: MITC4 assumed strains (Dvorkin & Bathe 1984), tied at the mid-edges;
//    elastic, k G h0 with k = 5/6. No shear locking, no spurious modes.
//  * Six DOFs per node: three translations and three rotation increments about the global
//    axes; the director is updated by the exact rotation d <- R(dpsi) d (Rodrigues). The
//    drilling rotation (about d) does not move the director; it gets a small stiffness in
//    the tangent only (drilling_factor), which never changes the converged solution.
//  * The tangent is the exact derivative of the residual (material, geometric and
//    rotational parts) on the rotations normal to the directors; its drilling rows and
//    columns are replaced by the small drilling stiffness. Projected this way the rotational
//    term is -(d.r_d)(I - d d^T): symmetric, so the tangent is symmetric whenever the
//    material tangent is (elastic, Hill with isotropic hardening) and CHOLMOD applies.
#include "forward/element/quad_shape.hpp"
#include "forward/element/shell_section.hpp"

#include <Eigen/Core>

#include <array>

namespace spifit::element {

struct ShellOptions {
  int thickness_points = 5;
  ThicknessRuleKind thickness_rule = ThicknessRuleKind::gauss;
  double shear_factor = 5.0 / 6.0;
  double drilling_factor = 1e-4;           // x mean rotational stiffness of the element
  // In-plane shear strain taken at the element centre (selective reduced integration): removes
  // the parasitic shear of the bilinear membrane in in-plane bending (twisted beam); keeps
  // the membrane patch test and the rank (the normal strains still see the hourglass modes).
  bool centre_membrane_shear = true;
  Eigen::Vector3d material_axis = Eigen::Vector3d::UnitX();  // rolling direction
  // false: residuals alone skip the layers' consistent tangents (ShellSection::set_layer_tangents;
  // explicit runs assemble no tangent).
  bool layer_tangents = true;
  // > 0: one in-plane point (the centre) carries the layers, and the strains' variation over
  // the element (e, kappa at the 2 x 2 points minus the centre's) gets an elastic section
  // stiffness of this fraction (physical hourglass stabilisation, Belytschko & Bindeman 1993).
  // Its tangent is exact too. 0: the four points carry layers.
  double hourglass_stiffness = 0.0;
};

struct PointKinematics;  // shell_q4.cpp

using Vec24 = Eigen::Matrix<double, 24, 1>;
using Mat24 = Eigen::Matrix<double, 24, 24>;
// Derivatives of an element's 24 DOF values (or forces) with respect to the sensitivity slots.
using SensDofs = Eigen::Matrix<double, 24, material::kSensitivitySlots>;

// From derivatives with respect to p = (x_I, d_I) (positions and directors, 6 per node) to
// the DOFs u = (translation, rotation increment): residual and exact tangent on the rotations
// normal to the directors (no drilling stiffness). Shared by the shell and its contact.
// symmetric: kp is symmetric, and ku's node blocks below the diagonal are mirrored from those
// above instead of computed.
void director_to_dofs(const NodeVectors& d, const Vec24& rp, const Mat24* kp, Vec24* ru, Mat24* ku, bool symmetric = false);

// Energies of an element's committed state [N mm], integrated over its reference area.
struct ElementEnergy {
  double elastic = 0.0;           // membrane and bending, layer by layer (SectionEnergy)
  double plastic = 0.0;           // plastic work of the layers
  double transverse_shear = 0.0;  // MITC4 shear: k G h0 |gamma|^2 / 2
};

struct ElementStatus {
  bool ok = true;
  int point = -1, layer = -1;  // in-plane Gauss point 0..3, layer from the bottom
  std::string reason;
  double suggested_scale = 1.0;
};

class ShellQ4 {
 public:
  // X: reference nodes; D: reference unit directors (nodal normals); thickness h0.
  ShellQ4(const NodeVectors& X, const NodeVectors& D, double thickness, const ShellSection::Law& law,
          const ThicknessRule& rule, const ShellOptions& options);

  // Residual (internal forces and moments, 6 per node: Fx Fy Fz Mx My Mz) and tangent at the
  // current nodes x and directors d. The layers' trial states are updated from the
  // committed ones.
  ElementStatus compute(const NodeVectors& x, const NodeVectors& d, Vec24* residual, Mat24* tangent);
  void commit();
  void revert();
  // Direct differentiation (docs/design/sensitivities.md): the sections keep their committed
  // states' derivatives with respect to the `count` parameters seeded in the law passed below.
  void enable_sensitivities(int count = material::kSensitivitySlots);
  // At the nodes x, d of the converged iterate (compute() there first). du null: the
  // pseudo-load, the derivative of the residual with respect to the parameters at fixed nodes
  // (through the law's parameters and the committed state's derivatives), into *load (DOF
  // order, rotations about x, y, z). du (the nodal DOFs' derivatives, rotations about x, y, z):
  // the sections' trial derivatives, which commit() keeps; load may then be null (given, it
  // receives the sections' part alone, not the total derivative: callers ask with du null). count: the
  // parameters in slots 0 .. count - 1; with room for three more slots, the pseudo-load pass
  // linearises the layers in their strains (ShellSection::pseudo_resultants) and the pass with du
  // that follows it only advances their derivatives: one Jet integration per increment, not two.
  // narrow (optional): `law` with fewer slots, for that pass when they suffice.
  ElementStatus sensitivities(const NodeVectors& x, const NodeVectors& d, const SensLaw& law, const SensDofs* du, SensDofs* load,
                              int count = material::kSensitivitySlots, const NarrowLaws* narrow = nullptr);
  // Committed state of the four sections (checkpoints; ShellSection::save_state).
  void save_state(io::BinaryWriter& w) const;
  void load_state(io::BinaryReader& r);
  // Whether the last compute()'s tangent was exact, and the switch (ShellSection::set_exact_tangents).
  bool tangent_was_exact() const {
    for (const auto& sec : sections_)
      if (!sec.tangent_was_exact()) return false;
    return true;
  }
  void set_exact_tangents(bool exact) {
    for (auto& sec : sections_) sec.set_exact_tangents(exact);
  }
  // Their committed derivatives, after enable_sensitivities (ShellSection::save_sensitivities).
  void save_sensitivities(io::BinaryWriter& w, int count) const;
  void load_sensitivities(io::BinaryReader& r, int count);

  // Energies at the committed nodes x and directors d (the sections' committed states).
  ElementEnergy energy(const NodeVectors& x, const NodeVectors& d) const;
  double reference_area() const;
  // The in-plane points that carry layers: 4 (2 x 2 Gauss), or 1 (the centre, over the whole
  // area) with hourglass stabilisation.
  int points() const { return static_cast<int>(sections_.size()); }
  const ShellSection& section(int point) const { return sections_[static_cast<std::size_t>(point)]; }
  // The options the element was built with (its rolling direction among them).
  const ShellOptions& options() const { return options_; }

 private:
  struct PointGeometry {
    Eigen::Matrix<double, 2, 4> dN;  // Cartesian shape derivatives in the element frame
    Eigen::Matrix2d K;               // d xi_alpha / d y_a (row a, column alpha), element frame
    double weight = 0.0;             // Gauss weight x area Jacobian
    double xi = 0.0, eta = 0.0;
    Eigen::Vector3d F0ref, F1ref;    // reference tangents (the frame vectors)
    Eigen::Vector3d kappa_ref;       // reference "curvature" terms (engineering)
    Eigen::Matrix3d Q;               // strain vector: element frame -> material frame
  };
  struct TyingPoint {
    Eigen::Vector4d N;      // shape functions at the tying point
    Eigen::Vector4d dN;     // natural derivative along its direction (xi for B/D, eta for A/C)
    double gamma_ref = 0.0; // a_alpha . d in the reference configuration
  };
  // The one-point version of compute (hourglass_stiffness > 0).
  ElementStatus compute_reduced(const NodeVectors& x, const NodeVectors& d, Vec24* residual, Mat24* tangent);
  // The strains (e, kappa) at the 2 x 2 points minus the centre's, element frame (and the
  // points' kinematics, if asked).
  std::array<Vec6, 4> strain_variation(const NodeVectors& x, const NodeVectors& d, const Vec6& centre,
                                       std::array<PointKinematics, 4>* kinematics = nullptr) const;
  // MITC4 transverse shear strains (element frame) at the four Gauss points, and the tying
  // points' a_alpha and d (shared by compute and energy).
  struct TransverseShear {
    std::array<Eigen::Vector3d, 4> a_t, d_t;
    std::array<Eigen::Vector2d, 4> gamma;  // per Gauss point
  };
  TransverseShear transverse_shear(const NodeVectors& x, const NodeVectors& d) const;
  // The one-point version of sensitivities(): the centre's section, the hourglass stiffness's
  // derivatives through the law's elasticity, the shear's (dp: the p-variables' derivatives;
  // pseudo: the pseudo-load).
  ElementStatus sensitivities_reduced(const NodeVectors& x, const NodeVectors& d, const SensLaw& law, const SensDofs& dp, bool pseudo,
                                      SensDofs* load, int count, const NarrowLaws* narrow, const TransverseShear& shear,
                                      const material::SensitivityRow& dks);
  ShellOptions options_;
  double h0_;
  double shear_modulus_;
  // The layers' tangent is symmetric (associated flow with isotropic hardening; kinematic
  // hardening makes it non-symmetric): the element's tangent is assembled from its upper node
  // blocks.
  bool symmetric_material_ = true;
  std::array<PointGeometry, 4> points_;
  PointGeometry centre_;  // the element centre (in-plane shear)
  std::array<TyingPoint, 4> tying_;  // B (0,-1), D (0,1) for gamma_xi; A (-1,0), C (1,0) for gamma_eta
  std::vector<ShellSection> sections_;
  double area_ = 0.0;
  Mat6 hourglass_stiffness_ = Mat6::Zero();  // section stiffness of the strain variation (element frame)
};

}  // namespace spifit::element
