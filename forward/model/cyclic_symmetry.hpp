#pragma once
// Cyclic (rotational) symmetry of a pie about the z axis (thesis Fig. 8.4; docs/design/cone.md,
// "Virtual tools"): every node of the second pie edge carries the DOFs of its partner on the
// first edge, rotated by the pie angle: u_s = R(gamma) u_m and psi_s = R(gamma) psi_m. Nodes
// on the axis belong to both edges: their in-plane translations and rotations vanish
// (unless gamma = 360 deg). A node without rotations (a solid's) ties its translations only.
#include "forward/mesh/mesh.hpp"
#include "forward/solver/dof_constraints.hpp"

namespace spifit::model {

class FeModel;

// Pairs the nodes of master_set and slave_set of the model's mesh (slave = master rotated by
// angle_deg about z, matched within tol) and adds the ties: translations, and rotations at nodes
// that have them. Throws std::invalid_argument naming the first node without a partner.
void tie_cyclic_edges(const FeModel& model, const std::string& master_set, const std::string& slave_set, double angle_deg,
                      solver::DofConstraints* constraints, double tol = 1e-8);

}  // namespace spifit::model
