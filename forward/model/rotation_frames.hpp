#pragma once
// Nodal rotation frames: five unknowns per node of a shell (docs/design/numerics-shell.md, "Nodal
// rotation frames"). At every node whose three rotations are free (neither prescribed, tied,
// nor the master of a tie), the rotation unknowns are taken in the frame (t1, t2, d) of the
// node's current director d instead of about x, y, z, and the one about d -- the drilling
// rotation, which moves no director and has only the tangent's regularising stiffness -- is
// prescribed to zero, so it leaves the factorisation. The frame is carried from the reference
// director by the shortest rotation onto d: smooth in d, so nearby directors have nearby frames.
#include "forward/solver/dof_constraints.hpp"

#include <Eigen/Core>

#include <vector>

namespace spifit::model {

// A unit vector normal to the unit vector d: the global axis least aligned with d, made normal
// to it (x for d = +-z). With d x it, an orthonormal pair normal to d.
Eigen::Vector3d least_aligned_normal(const Eigen::Vector3d& d);

class NodalRotationFrames {
 public:
  // No node framed.
  NodalRotationFrames() = default;
  // Frames at every node whose rotation DOFs 6n+3..6n+5 are free in c; prescribes their drilling
  // DOF 6n+5 to zero in c (call before c.finalize()). d0: reference directors.
  NodalRotationFrames(const std::vector<Eigen::Vector3d>& d0, solver::DofConstraints* c);

  bool empty() const { return framed_.empty(); }
  bool framed(int node) const { return !framed_.empty() && framed_[static_cast<std::size_t>(node)]; }
  int count() const { return count_; }
  // Columns t1, t2, d of the frame of a node with director d.
  Eigen::Matrix3d frame(int node, const Eigen::Vector3d& d) const;
  // In place, on a full 6-DOF-per-node vector: the rotation parts of framed nodes from x, y, z to
  // the frames of the directors ds (to_frame) or back.
  void rotate(const std::vector<Eigen::Vector3d>& ds, bool to_frame, Eigen::VectorXd* v) const;

 private:
  std::vector<Eigen::Vector3d> d0_;
  std::vector<char> framed_;               // per node
  std::vector<Eigen::Vector3d> frame_t1_;  // per node: t1 of the frame of the reference director
  int count_ = 0;
};

}  // namespace spifit::model
