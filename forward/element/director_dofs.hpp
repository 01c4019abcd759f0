#pragma once
// From an element's derivatives with respect to its nodes' positions and directors (6 per node)
// to its DOFs (translations and rotation increments): director_to_dofs (declared in shell_q4.hpp,
// shared with the contact), and the helpers of ShellQ4's two integration paths.
#include "forward/element/shell_q4.hpp"

namespace spifit::element {

// The node blocks (J, I), J > I, of a symmetric 24 x 24 matrix from its blocks (I, J).
void mirror_upper_blocks(Mat24& k);

// Derivatives of the DOFs (translations, rotation increments about x, y, z; a column per
// sensitivity slot) as derivatives of the positions and directors: dd_I = dpsi_I x d_I.
SensDofs director_variable_derivatives(const NodeVectors& d, const SensDofs& du);

// The other way, for forces: the derivatives of forces on the positions and directors (a column
// per slot, the first `count`) as derivatives of the forces and moments on the DOFs
// (director_to_dofs, linear in the forces); the other columns zero.
SensDofs director_force_derivatives(const NodeVectors& d, const SensDofs& rp, int count);

// The element's residual and tangent on its DOFs from their derivatives rp and kp (kp null:
// the residual alone) with respect to the positions and directors (director_to_dofs), the
// drilling stiffness added; a failure if the forces are not finite.
ElementStatus dof_results(const NodeVectors& d, const Vec24& rp, const Mat24* kp, bool symmetric, double drilling_factor, double area,
                          Vec24* residual, Mat24* tangent);

}  // namespace spifit::element
