#pragma once
// The finite-element model of a sheet, over an element family (element_family.hpp): the mesh,
// the nodes' DOF layout (6 per node with a director, ux uy uz then rotation increments about x y
// z, or in the node's frame: use_nodal_rotation_frames; 3 per node without), the nodal
// configurations (committed / iterate / trial) the Newton solver moves, concentrated loads, and
// additive contributions (the tool's contact, tool_contact.hpp) that the family evaluates with its
// elements. What is particular to one family stays in the family: ShellModel (shell_model.hpp) is
// this model over the ShellQ4 family with the shell's accessors. Energy account, lumped mass,
// VTU frames and checkpoints are free functions of their own files.
#include "forward/mesh/mesh.hpp"
#include "forward/model/element_contribution.hpp"
#include "forward/model/element_family.hpp"
#include "forward/model/rotation_frames.hpp"
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/nonlinear_problem.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spifit::model {

class FeModel : public solver::NonlinearProblem {
 public:
  // The model of the mesh's cells with the family's elements; the family refers to the mesh,
  // which must outlive the model.
  FeModel(const mesh::Mesh& mesh, std::unique_ptr<ElementFamily> family);

  // DOF `component` (0-2 displacement, 3-5 rotation) of a node.
  int node_dof(int node, int component) const { return dof_offset_[static_cast<std::size_t>(node)] + component; }
  // DOFs of a node: 6 (with a director) or 3.
  int node_dofs(int node) const { return node_dofs_[static_cast<std::size_t>(node)]; }
  // "node N (x, y, z) displacement|rotation x|y|z" at the committed configuration ("rotation
  // t1|t2|normal (nodal frame)" at a node with a rotation frame).
  std::string describe_dof(int dof) const override;

  // Five unknowns per node (rotation_frames.hpp): frames at every node whose three rotations
  // are free in c, whose drilling DOF is prescribed to zero in c. The Newton iterates are those
  // of the six-DOF model up to round-off. Full DOF vectors the solver exchanges with the model
  // (residuals, corrections, increment_from_committed, external_forces) carry those nodes'
  // rotation parts in their frames; internal_forces() and all committed results stay in x, y,
  // z. Call before c.finalize() and the first solve. Returns the number of nodes with a frame.
  // std::invalid_argument on a model with nodes without rotations.
  int use_nodal_rotation_frames(solver::DofConstraints* c);
  bool has_rotation_frame(int node) const { return frames_.framed(node); }
  // Columns t1, t2, d of the rotation frame of a framed node with director d (tests).
  Eigen::Matrix3d rotation_frame(int node, const Eigen::Vector3d& d) const { return frames_.frame(node, d); }
  const mesh::Mesh& mesh() const { return *mesh_; }
  int num_nodes() const { return mesh_->num_nodes(); }
  int num_elements() const { return family_->num_elements(); }
  const ElementFamily& family() const { return *family_; }

  // f_ext(lambda) += lambda x amplitude on this DOF (forces N, moments N mm).
  void add_nodal_load(int dof, double amplitude);
  // Internal forces at the current iterate (full vector): reactions at supported DOFs.
  Eigen::VectorXd internal_forces();

  // Adds a contribution (summed after the element's own forces, in the order added) and
  // returns it. Add before the first increment.
  template <typename C>
  C& add_contribution(std::unique_ptr<C> c) {
    C& ref = *c;
    contributions_.push_back(std::move(c));
    return ref;
  }
  const std::vector<std::unique_ptr<ElementContribution>>& contributions() const { return contributions_; }

  // NonlinearProblem
  void begin_increment(double lambda0, double lambda1) override;
  int num_dofs() const override { return num_dofs_; }
  const std::vector<std::vector<int>>& element_dofs() const override { return element_dofs_; }
  solver::ElementEvaluation evaluate_element(int e, Eigen::VectorXd* re, Eigen::MatrixXd* ke) override;
  Eigen::VectorXd external_forces(double lambda) const override;
  void set_trial(const Eigen::VectorXd& delta, double alpha) override;
  void accept_trial() override;
  void commit(double lambda) override;
  void revert() override;
  Eigen::VectorXd increment_from_committed() const override;

  // Direct differentiation (docs/design/sensitivities.md): from the next increment on, the
  // model carries the derivatives of its state with respect to `count` parameters, those of
  // `material` (the family's card) seeded by `seeds` in slots 0 .. count - 1; the Newton solver
  // then solves for the DOFs' derivatives after every converged increment. Call before the
  // first increment. std::invalid_argument (the reason) for a count outside 1 to
  // material::kSensitivitySlots, a family or a contribution without sensitivities.
  void enable_sensitivities(const std::vector<material::FieldSeed>& seeds, int count, const material::MaterialParams<double>& material);
  int sensitivity_count() const override { return sensitivity_count_; }
  solver::ElementEvaluation sensitivity_load(Eigen::MatrixXd* load) override;
  solver::ElementEvaluation update_sensitivities(const Eigen::MatrixXd& du) override;
  bool tangent_was_exact() const override { return family_->tangent_was_exact(); }
  void set_exact_tangents(bool exact) override { family_->set_exact_tangents(exact); }
  // Committed derivative of the contributions' total force (rows x, y, z; one column per
  // parameter): with the tool's contact alone, of ToolContact::force(), the force on the tool.
  const Eigen::Matrix<double, 3, Eigen::Dynamic>& contribution_force_sensitivity() const { return force_sensitivity_; }
  // Committed derivative of node n's position (rows x, y, z; one column per parameter); zero
  // before the first increment with sensitivities.
  Eigen::Matrix<double, 3, Eigen::Dynamic> position_sensitivity(int node) const {
    if (position_sensitivity_.size() == 0) return Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, sensitivity_count_);
    return position_sensitivity_.middleRows(dof_offset_[static_cast<std::size_t>(node)], 3);
  }

  // Committed results. Directors are those of nodes with rotations (zero at the others).
  Eigen::Vector3d displacement(int node) const { return x_[static_cast<std::size_t>(node)] - mesh_->nodes[static_cast<std::size_t>(node)]; }
  const Eigen::Vector3d& position(int node) const { return x_[static_cast<std::size_t>(node)]; }
  const Eigen::Vector3d& director(int node) const { return d_[static_cast<std::size_t>(node)]; }
  const std::vector<Eigen::Vector3d>& positions() const { return x_; }
  const std::vector<Eigen::Vector3d>& directors() const { return d_; }
  const Eigen::Vector3d& reference_director(int node) const { return d0_[static_cast<std::size_t>(node)]; }
  double load_factor() const { return lambda_; }
  // Committed thickness of element e (the family's) and of each node (mean of its elements).
  double element_thickness(int e) const { return family_->element_thickness(e); }
  std::vector<double> nodal_thickness() const;
  // With sensitivities: the committed derivative of nodal_thickness (nodes x parameters).
  Eigen::MatrixXd nodal_thickness_sensitivity() const;
  double load_work() const { return load_work_; }  // work of the nodal loads so far [N mm]
  const std::vector<std::string>& warnings() const { return family_->warnings(); }
  // Nodes of element e, in the order of its DOFs.
  const std::vector<int>& element_nodes(int e) const { return element_nodes_[static_cast<std::size_t>(e)]; }

  // Checkpoints (model_archive.hpp): the committed state is replaced and the iterate and trial
  // configurations reset to it. Sizes are the caller's to check.
  ElementFamily& family_state() { return *family_; }
  void restore_committed(double lambda, std::vector<Eigen::Vector3d> x, std::vector<Eigen::Vector3d> d, double load_work);
  // With sensitivities: the committed derivatives of the DOFs, of the contributions' force, of the
  // elements' and of the contributions' histories (bit-exact); load_sensitivities resets the
  // trial derivatives to them. io::ArchiveError on a mismatch.
  void save_sensitivities(io::BinaryWriter& w) const;
  void load_sensitivities(io::BinaryReader& r);

 protected:
  std::vector<std::pair<int, double>>& loads() { return loads_; }

 private:
  const mesh::Mesh* mesh_;
  std::unique_ptr<ElementFamily> family_;
  std::vector<int> node_dofs_, dof_offset_, dof_node_;
  int num_dofs_ = 0;
  std::vector<std::vector<int>> element_nodes_, element_dofs_;
  std::vector<Eigen::Vector3d> d0_;
  std::vector<Eigen::Vector3d> x_, d_;            // committed
  std::vector<Eigen::Vector3d> xi_, di_;          // iterate
  std::vector<Eigen::Vector3d> xt_, dt_;          // trial
  Eigen::VectorXd increment_, increment_trial_;   // sum of accepted corrections in this increment
  std::vector<std::pair<int, double>> loads_;
  double lambda_ = 0.0;
  double load_work_ = 0.0;                        // committed work of the nodal loads [N mm]
  std::vector<std::unique_ptr<ElementContribution>> contributions_;
  NodalRotationFrames frames_;
  int sensitivity_count_ = 0;
  // Element e's rows of a DOFs x parameters matrix, in evaluate()'s DOF order, padded to the
  // family's derivative slots.
  Eigen::MatrixXd element_sensitivity(const Eigen::MatrixXd& global, int e) const;
  Eigen::Matrix<double, 3, Eigen::Dynamic> force_sensitivity_, force_sensitivity_trial_;
  Eigen::MatrixXd position_sensitivity_, position_sensitivity_trial_;  // DOFs x parameters, rotations about x, y, z
};

}  // namespace spifit::model
