#pragma once
// The Moving Spherical Tool (MST) contact of the explicit scheme (thesis §5.2-5.3; docs/design/
// explicit.md, "MST contact"): the contact forces are not a penalty on the penetration but are
// chosen after each step, so that at the end of the next step the tool-side surface touches the
// sphere without penetrating it and Coulomb's law holds.
//
// After a step the accelerations without contact are known, hence where every node would be at
// the end of the next step. A force f added at a node changes that position by dt^2 T M^-1 T^T f
// (thesis eq. 5.11; T the constraints' expansion, M the reduced lumped mass). Around the tool
// (the "oil stain" neighbourhood of eq. 5.13, grown from the last one) each element gives one
// potential contact point: the point of its tool-side surface (the mid-surface offset by h/2
// along the directors) closest to the tool's next centre. Each point carries a normal force P
// and two friction components (F_s, F_t) in its local axes, spread to the element's nodes by
// the shape functions (eq. 5.25); their effect on every point's gap and slip is one small dense
// system (eqs. 5.24-5.28). The conditions of thesis Fig. 5.7 (stick: d = R and no slip; slide:
// d = R and |F_f| = mu P against the slip; no contact: P = 0 and d >= R) are solved as a
// complementarity problem by projected Gauss-Seidel sweeps: P >= 0 closing the gap, then the
// friction cancelling the slip, cut to the cone. The thesis switches the points' states all at
// once instead; that can cycle between neighbouring points, the sweeps converge to the one
// solution (docs/design/explicit.md, "MST contact"). Without friction the normal problem alone
// is solved exactly by an active-set method (normal_contact_lcp.hpp).
// Virtual tools of a pie (ToolContact::set_copies) are further spheres with their own points.
#include "forward/solver/dof_constraints.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::model {

class ShellModel;

struct MstStatistics {
  long solves = 0;                 // steps with at least one point in contact
  long sweeps = 0;                 // Gauss-Seidel sweeps (with friction) or active sets (without) over all solves
  long unconverged = 0;            // solves that ended at the sweep or set limit (the last forces kept)
  int max_points = 0;              // most potential contact points in one solve
  double max_penetration = 0.0;    // largest penetration found at a contact point before a solve [mm]
  double max_friction_ratio = 0.0; // largest |F_f| / (mu P) over points in contact (mu > 0)
  double work = 0.0;               // work of the contact forces on the sheet [N mm]
};

class MovingSphereContact {
 public:
  using PathFunction = std::function<Eigen::Vector3d(double lambda)>;  // the real tool's centre
  // reduced_mass: the explicit solver's diag(T^T M T). rotations_deg: the virtual tools' angles
  // (empty: the real tool alone).
  MovingSphereContact(const ShellModel& model, const solver::DofConstraints& constraints, Eigen::VectorXd reduced_mass, double radius,
                      double friction, PathFunction path, std::vector<double> copies_deg = {});

  // The forces on the sheet (full DOF vector, translations) for the next step of dt to
  // lambda_next, given the reduced increment it would take without them; the model is at the
  // end of the last step. solver::ExplicitSolver::ContactForces.
  Eigen::VectorXd forces(double dt, double lambda_next, const Eigen::VectorXd& next_increment);

  // Force BY the sheet ON the real tool from the last solve [N] (the copies' rotated back).
  const Eigen::Vector3d& tool_force() const { return tool_force_; }
  const MstStatistics& statistics() const { return stats_; }
  int last_contact_points() const { return last_points_; }

  // Checkpoints of an explicit run, bit-exact: the followed thickness, the neighbourhoods the
  // next search grows from, the last forces and positions (the next step's work pairs with
  // them), the tool force and the statistics. Loaded into a contact built alike;
  // io::ArchiveError for another model size or number of tools.
  void save_state(io::BinaryWriter& w) const;
  void load_state(io::BinaryReader& r);

 private:
  struct Point;
  const ShellModel& model_;
  const solver::DofConstraints& constraints_;
  Eigen::VectorXd mass_;
  double radius_, friction_;
  PathFunction path_;
  std::vector<Eigen::Matrix3d> rotations_;
  std::vector<std::vector<int>> node_elements_;   // elements around each node
  std::vector<std::vector<int>> neighbourhood_;   // per tool, the last one
  std::vector<std::pair<int, Eigen::Vector3d>> last_forces_;  // node, force of the last solve
  std::vector<Eigen::Vector3d> last_positions_;
  std::vector<double> thickness_;  // per element, the thickness whose half offsets the tool-side surface (follow_thickness)
  Eigen::Vector3d tool_force_ = Eigen::Vector3d::Zero();
  MstStatistics stats_;
  int last_points_ = 0;

  std::vector<int> grow_neighbourhood(int tool, const Eigen::Vector3d& centre);
  // Moves each element's thickness_ towards its committed thickness by the tool's travel of the next step.
  void follow_thickness(double lambda_next);
  // Where a node's translation goes, and its director, over the next step without contact forces.
  Eigen::Vector3d next_move(int node, const Eigen::VectorXd& increment) const;
  Eigen::Vector3d next_director(int node, const Eigen::VectorXd& increment) const;
  // One potential contact point per element of the tool's neighbourhood.
  std::vector<Point> candidates(int tool, double lambda_next, const Eigen::VectorXd& increment);
  // The candidates without those that are another's contact (shared boundaries, close points).
  std::vector<Point> distinct(const std::vector<Point>& found) const;
  Eigen::MatrixXd compliance(const std::vector<Point>& points, double dt) const;
  Eigen::VectorXd solve(const std::vector<Point>& points, const Eigen::MatrixXd& W);
  Eigen::VectorXd solve_frictionless(const std::vector<Point>& points, const Eigen::MatrixXd& W);
};

}  // namespace spifit::model
