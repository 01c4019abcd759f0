#pragma once
// History of one element of a cone (thesis §9.4 follows element 1469 of the fine
// 70-degree cone, at r = 75.55 mm, theta = 22.5 deg): strains, curvatures and stresses in the
// initial polar frame, per integration point through the thickness, after every increment.
//
// Frame. e_r and e_theta are the radial and circumferential unit vectors at the polar angle of
// the element's initial centroid (projected on the initial tangent plane). The strains are
// Green-Lagrange strains of the total Lagrangian shell, whose components on the initial
// orthonormal frame are the components on the convected frame (F e_r, F e_theta): e_r becomes
// the direction "aligned with the wall of the cone" of the thesis (§9.4.1: its y axis, radial
// along the wall; x circumferential). Shear is engineering, gamma_rt = 2 E_rt.
//
// Where. Strains at the element centre (xi = eta = 0) from the committed nodal positions and
// directors with the bilinear shape functions, as ShellQ4 forms them at its Gauss points:
//   membrane  E_aa = (f_a . f_a - 1) / 2,  gamma_rt = f_r . f_theta,  f_a = F e_a,
//   bending   K_aa = f_a . d_a,  K_rt = f_r . d_theta + f_theta . d_r, each minus its initial
//             value (d_a: derivative of the director along e_a; the linear term in z of the
//             Green strain of the fibre at z along the director, as ShellQ4's kappa),
//   layer at zeta in [-1, 1]:  E(zeta) = E + zeta h/2 K  (h = committed element thickness).
// lambda_r = |F e_r| is the radial stretch of the mid-surface and E_rr = (lambda_r^2 - 1)/2
// its radial membrane Green strain (thesis eq. 9.4 for the circumferential one; §9.4.4: 420 %
// at the end of the 100-contour cone, sine law 377 %). Stresses and the equivalent plastic
// strain are those of the element's layers (ShellSection, committed), averaged over its 2 x 2
// Gauss points and rotated from the material frame (rolling direction projected on the initial
// tangent plane) into (e_r, e_theta): the layer stress is the Kirchhoff stress conjugate to the
// logarithmic strain in the rotated material frame (equal to the Cauchy stress up to the
// elastic volume change). The equivalent stress is von Mises's (thesis Figs. 9.45, 9.46) of
// these averaged components; its thickness mean uses the through-thickness weights.
#include "forward/element/quad_shape.hpp"
#include "forward/element/thickness_rule.hpp"
#include "forward/mesh/mesh.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spifit::model {
class ShellModel;
}

namespace spifit::scene {

// The element of the initial mesh whose centroid lies nearest (in the x-y plane) to the point
// at radius r and polar angle theta_deg; ties go to the lowest element index. -1 for an empty
// mesh.
int nearest_element(const mesh::Mesh& m, double r, double theta_deg);

struct PolarStrains {
  Eigen::Vector3d membrane = Eigen::Vector3d::Zero();  // E_rr, E_tt, gamma_rt
  Eigen::Vector3d bending = Eigen::Vector3d::Zero();   // K_rr, K_tt, K_rt [1/mm]; > 0 stretches the top (director side)
  double stretch_r = 1.0, stretch_theta = 1.0;          // |F e_r|, |F e_theta|
};

// Centre strains of a 4-node shell element: X, D initial nodes and unit directors, x, d
// current ones; the frame at the initial centroid's polar angle (0 on the axis).
PolarStrains centre_polar_strains(const element::NodeVectors& X, const element::NodeVectors& D, const element::NodeVectors& x,
                                  const element::NodeVectors& d);

// Tensor components (s_11, s_22, s_12) of a symmetric in-plane tensor in the frame (m1, m2),
// expressed in the frame (e_r, e_theta) with e_r = c m1 + s m2, e_theta = -s m1 + c m2.
Eigen::Vector3d rotate_tensor_components(const Eigen::Vector3d& s12, double c, double s);

// Von Mises equivalent of a plane stress (s_11, s_22, s_12).
double von_mises_plane_stress(const Eigen::Vector3d& s);

struct LayerHistory {
  double zeta = 0.0;
  Eigen::Vector3d strain = Eigen::Vector3d::Zero();  // Green E_rr, E_tt, gamma_rt at zeta (element centre)
  Eigen::Vector3d stress = Eigen::Vector3d::Zero();  // S_rr, S_tt, S_rt [MPa], Gauss-point mean
  double von_mises = 0.0, eqps = 0.0;
};

struct ElementHistoryRow {
  double thickness = 0.0;  // committed, mean of the Gauss points
  PolarStrains centre;
  std::vector<LayerHistory> layers;  // bottom to top
  double von_mises_mean = 0.0;       // through-thickness mean of the layers' von Mises stress
};

// The committed state of element e of the model. rule: the model's through-thickness rule. The
// layer stresses are turned from the element's material frame (its rolling direction,
// ShellModel::material_axis) into e_r, e_theta.
ElementHistoryRow element_history_row(const model::ShellModel& model, int e, const element::ThicknessRule& rule);

// history.csv columns and one row (docs/reference/file-formats.md "Cone scene").
std::vector<std::string> element_history_columns(int layers);
std::vector<double> element_history_values(double travel, double lambda, const ElementHistoryRow& row);

}  // namespace spifit::scene
