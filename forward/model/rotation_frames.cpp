#include "forward/model/rotation_frames.hpp"

#include <Eigen/Geometry>

#include <stdexcept>

namespace spifit::model {

Eigen::Vector3d least_aligned_normal(const Eigen::Vector3d& d) {
  Eigen::Index k = 0;
  d.cwiseAbs().minCoeff(&k);
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(k);
  return (e - e.dot(d) * d).normalized();
}

NodalRotationFrames::NodalRotationFrames(const std::vector<Eigen::Vector3d>& d0, solver::DofConstraints* c) : d0_(d0) {
  const auto nn = d0.size();
  if (c->num_dofs() != static_cast<int>(6 * nn))
    throw std::invalid_argument("nodal rotation frames: constraints of " + std::to_string(c->num_dofs()) + " DOFs for a model of " +
                                std::to_string(6 * nn));
  if (c->finalized()) throw std::logic_error("nodal rotation frames: call before DofConstraints::finalize()");
  const std::vector<char> master = c->master_flags();
  framed_.assign(nn, 0);
  frame_t1_.assign(nn, Eigen::Vector3d::Zero());
  for (std::size_t n = 0; n < nn; ++n) {
    bool free = true;
    for (int k = 3; k < 6; ++k) {
      const int i = static_cast<int>(6 * n) + k;
      free = free && !c->prescribed(i) && !c->tied(i) && !master[static_cast<std::size_t>(i)];
    }
    if (!free) continue;
    // Reference frame: x, y, z itself for a flat sheet in the xy plane.
    frame_t1_[n] = least_aligned_normal(d0_[n]);
    framed_[n] = 1;
    c->prescribe(static_cast<int>(6 * n) + 5, 0.0);
    ++count_;
  }
}

// The frame is carried from the reference director a to d by the shortest rotation (axis
// a x d), R t = t + v x t + v x (v x t) / (1 + c) with v = a x d, c = a . d. Beyond 150 deg of
// turn (never met in forming) any tangent will do: the frames are rebuilt from the directors at
// every use and nothing is carried in them from one configuration to another except the
// predictor, which is stored and used at the same directors.
Eigen::Matrix3d NodalRotationFrames::frame(int node, const Eigen::Vector3d& d) const {
  const auto n = static_cast<std::size_t>(node);
  const Eigen::Vector3d& a = d0_[n];
  const double c = a.dot(d);
  Eigen::Vector3d t1;
  if (c > -0.866) {
    const Eigen::Vector3d& t = frame_t1_[n];
    const Eigen::Vector3d v = a.cross(d);
    t1 = t + v.cross(t) + v.cross(v.cross(t)) / (1.0 + c);
    t1 = (t1 - t1.dot(d) * d).normalized();
  } else {
    t1 = least_aligned_normal(d);
  }
  Eigen::Matrix3d q;
  q.col(0) = t1;
  q.col(1) = d.cross(t1);
  q.col(2) = d;  // exactly the director the element uses: its drilling column is exactly decoupled
  return q;
}

void NodalRotationFrames::rotate(const std::vector<Eigen::Vector3d>& ds, bool to_frame, Eigen::VectorXd* v) const {
  for (std::size_t n = 0; n < framed_.size(); ++n) {
    if (!framed_[n]) continue;
    auto seg = v->segment<3>(static_cast<Eigen::Index>(6 * n + 3));
    if (seg.isZero(0.0)) continue;
    const Eigen::Matrix3d q = frame(static_cast<int>(n), ds[n]);
    const Eigen::Vector3d w = seg;
    if (to_frame) seg.noalias() = q.transpose() * w;
    else seg.noalias() = q * w;
  }
}

}  // namespace spifit::model
