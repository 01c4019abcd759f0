#pragma once
// The small-strain core of the one-point brick (the thesis's BWD3D, §3.1.2: 8 nodes, one
// integration point, hourglass control free of shear and volumetric locking): the uniform
// gradient of an 8-node hexahedron (Flanagan & Belytschko 1981), its hourglass modes, and a
// physical stabilisation taken from the incompatible-modes hexahedron (Wilson, Taylor et al.
// 1976, with Taylor's correction for distorted shapes). The stabilisation acts on the twelve
// hourglass amplitudes only, so it leaves constant-strain fields alone (the patch test holds on
// distorted meshes) and gives the hourglass modes the energy the incompatible-modes element
// gives them: exact pure bending of rectangular elements with one element through the thickness,
// and no volumetric locking (the one-point part carries the volume change). The element is
// linear here; its corotational, elastic-plastic form builds on these operators.
//
// Node order is VTK's (mesh::Hex): isoparametric corners (xi, eta, zeta) = (-1,-1,-1),
// (1,-1,-1), (1,1,-1), (-1,1,-1), then the same at zeta = +1. Strain and stress in Voigt order
// xx, yy, zz, xy, xz, yz with engineering shears (material/stress_space.hpp, Dim = 6); DOFs ux,
// uy, uz per node.
#include <Eigen/Core>

#include <array>
#include <vector>

namespace spifit::element {

using HexCorners = std::array<Eigen::Vector3d, 8>;
using HexVector = Eigen::Matrix<double, 24, 1>;
using HexMatrix = Eigen::Matrix<double, 24, 24>;
using Voigt6Matrix = Eigen::Matrix<double, 6, 6>;

// dN_I / d(xi, eta, zeta) at a point s of the parent cube (3 x 8).
Eigen::Matrix<double, 3, 8> hex_parent_derivatives(const Eigen::Vector3d& s);
// J(r, c) = d x_c / d s_r for the corners X and dN = hex_parent_derivatives(s).
Eigen::Matrix3d hex_jacobian(const HexCorners& X, const Eigen::Matrix<double, 3, 8>& dN);

// Isotropic elastic matrix (Voigt, engineering shears).
Voigt6Matrix isotropic_elasticity(double E, double nu);

struct HexUniformGradient {
  // b(k, I) = (1 / V) integral of dN_I / dx_k over the element: sum_I b(k, I) x_I = e_k exactly.
  Eigen::Matrix<double, 3, 8> b;
  double volume = 0.0;
};
// Throws std::invalid_argument when the Jacobian is not positive at a Gauss point.
HexUniformGradient hex_uniform_gradient(const HexCorners& X);

// Strain-displacement matrix of a gradient (3 x 8) in Voigt order.
Eigen::Matrix<double, 6, 24> hex_strain_matrix(const Eigen::Matrix<double, 3, 8>& b);

// The hourglass operator G (12 x 24): amplitude q(3 a + i) of hourglass mode a (a = 0..3: the
// nodal values of eta zeta, zeta xi, xi eta, xi eta zeta) in displacement component i, with
// q = G u zero for every linear field u = c + A x (Flanagan & Belytschko's gamma vectors).
Eigen::Matrix<double, 12, 24> hex_hourglass_operator(const HexCorners& X, const HexUniformGradient& g);
// The nodal displacements of unit hourglass amplitudes: H (24 x 12), G H = I on parallelepipeds.
Eigen::Matrix<double, 24, 12> hex_hourglass_shapes();

// V B^T D B with the uniform gradient: the one-point stiffness, rank 6 (twelve hourglass modes
// and six rigid-body modes without energy).
HexMatrix hex_one_point_stiffness(const HexCorners& X, const Voigt6Matrix& D);
// 2 x 2 x 2 Gauss points, displacement-based: locks in bending and near incompressibility
// (for comparison).
HexMatrix hex_full_stiffness(const HexCorners& X, const Voigt6Matrix& D);
// The incompatible-modes hexahedron: nine modes (1 - xi_k^2) per direction, condensed out, with
// their gradients taken at the centre and scaled by det J0 / det J (Taylor's correction).
HexMatrix hex_incompatible_modes_stiffness(const HexCorners& X, const Voigt6Matrix& D);
// H^T K_im H (12 x 12): the incompatible-modes element's stiffness of unit hourglass amplitudes,
// in the amplitudes' order of hex_hourglass_operator.
Eigen::Matrix<double, 12, 12> hex_hourglass_stiffness(const HexCorners& X, const Voigt6Matrix& D);
// Its derivative along dD at D (direct differentiation: the stabilisation built on a consistent
// tangent that moves with the parameters).
Eigen::Matrix<double, 12, 12> hex_hourglass_stiffness_derivative(const HexCorners& X, const Voigt6Matrix& D, const Voigt6Matrix& dD);
// The same along several directions at once (the blocks of D factorised once).
std::vector<Eigen::Matrix<double, 12, 12>> hex_hourglass_stiffness_derivatives(const HexCorners& X, const Voigt6Matrix& D,
                                                                              const std::vector<Voigt6Matrix>& dD);
// G^T (H^T K_im H) G: the hourglass stabilisation (K_im the incompatible-modes stiffness).
HexMatrix hex_stabilisation_stiffness(const HexCorners& X, const Voigt6Matrix& D);

}  // namespace spifit::element
