#pragma once
// The constraints of a coarsened sheet's hanging nodes (mesh::Mesh::constrained_nodes): a node in
// the middle of a larger element's edge follows the edge's ends, u_h = sum w_k u_k.
//
// Translations are tied in x, y, z. Rotations are tied in the nodal rotation frames
// (rotation_frames.hpp): the hanging node's two rotations normal to its director are the weighted
// sums of its masters' two, and no drilling rotation enters. Tied in x, y, z instead, a master's
// drilling rotation, which moves none of its own elements and has only the shell's small drilling
// stiffness, would turn the hanging node's director; Newton then stalled on those rotations
// (the line test could not pass its first millimetre). Neighbouring frames are carried from the
// same reference frame by the directors' shortest rotations, so the frame components of nearby
// nodes differ by the angle between their directors: small where sheets are coarsened, away from
// the tool. Masters that are supported (clamped edges, a symmetry plane) are not framed; their
// x, y, z rotations are then the frame components of the hanging node's frame up to that angle
// (on y = 0 of a half model, exactly: t2 = y and rotations about t1 are held).
//
// A framed hanging node with a master that is not framed and has both in-plane rotations free
// (x and y not prescribed: the edge of a pie, whose rotations are cyclically tied) would tie the
// hanging node's turning frame to the master's fixed x, y axes, a tie that changes with the
// configuration while the solver's is fixed: on the short cone Newton then went down to the
// minimum increment within 1.25 mm of travel. Such a hanging node keeps its own two rotations
// (its translations stay tied); only its fine neighbours turn it.
#include "forward/mesh/mesh.hpp"
#include "forward/solver/dof_constraints.hpp"

namespace spifit::model {

class FeModel;

// Before FeModel::use_nodal_rotation_frames: ties the hanging nodes' translations.
void tie_hanging_translations(const FeModel& model, solver::DofConstraints* c);
// After use_nodal_rotation_frames, before c->finalize(): ties their two frame rotations (x and y
// rotations for a node without a frame), except next to a master described above. Returns the
// number of hanging nodes whose rotations were tied (none in a model without rotations).
int tie_hanging_rotations(const FeModel& model, solver::DofConstraints* c);

}  // namespace spifit::model
