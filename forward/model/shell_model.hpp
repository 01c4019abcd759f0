#pragma once
// A shell finite-element model: mesh, ShellQ4 elements, six DOFs per node (ux uy uz, then
// rotation increments about x y z, or in the node's frame: use_nodal_rotation_frames), nodal
// directors, concentrated loads, additive element contributions (the tool's contact,
// tool_contact.hpp), and the configuration bookkeeping the Newton solver needs (committed /
// iterate / trial). Energy account, lumped mass, VTU frames and checkpoints are free functions
// of their own files (model_energies.hpp, lumped_mass.hpp, model_vtu.hpp, model_archive.hpp).
#include "forward/element/shell_q4.hpp"
#include "forward/mesh/mesh.hpp"
#include "forward/model/element_contribution.hpp"
#include "forward/model/rotation_frames.hpp"
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/nonlinear_problem.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spifit::model {

struct ShellModelOptions {
  element::ShellOptions shell;
  // Thickness over the shortest element edge: a warning above warn_..., an error above max_...
  // (the thesis's fine cone mesh has t/l = 1.7; docs/design/numerics-shell.md).
  double warn_thickness_over_length = 1.0;
  double max_thickness_over_length = 3.0;
  // Material axes of the elements. `fixed` (default): the rolling direction is
  // shell.material_axis everywhere, as in a rolled sheet. `polar`: shell.material_axis is read in
  // each element's polar frame (e_r, e_theta, z) at its reference centroid, so the rolling
  // direction turns with the polar angle; the material is then the same in every pie of a disc,
  // which is what the cyclic ties of a pie model assume (docs/design/cone.md, "Material axes").
  enum class MaterialAxes { fixed, polar };
  MaterialAxes material_axes = MaterialAxes::fixed;
};

// "fixed" or "polar"; false otherwise (the [sheet] material_axes key, summary.json).
bool material_axes_from_string(const std::string& s, ShellModelOptions::MaterialAxes* axes);
const char* to_string(ShellModelOptions::MaterialAxes axes);

class ShellModel final : public solver::NonlinearProblem {
 public:
  // Throws std::invalid_argument for a degenerate element (naming it), t/l above the limit,
  // an unsupported number of thickness points, or bad options.
  ShellModel(const mesh::Mesh& mesh, double thickness, const material::MaterialParams<double>& material,
             const ShellModelOptions& options);

  static int dof(int node, int component) { return 6 * node + component; }
  // "node N (x, y, z) displacement|rotation x|y|z" at the committed configuration ("rotation
  // t1|t2|normal (nodal frame)" at a node with a rotation frame).
  std::string describe_dof(int dof) const override;

  // Five unknowns per node (rotation_frames.hpp): frames at every node whose three rotations
  // are free in c, whose drilling DOF is prescribed to zero in c. The Newton iterates are those
  // of the six-DOF model up to round-off. Full DOF vectors the solver exchanges with the model
  // (residuals, corrections, increment_from_committed, external_forces) carry those nodes'
  // rotation parts in their frames; internal_forces() and all committed results stay in x, y,
  // z. Call before c.finalize() and the first solve. Returns the number of nodes with a frame.
  int use_nodal_rotation_frames(solver::DofConstraints* c);
  bool has_rotation_frame(int node) const { return frames_.framed(node); }
  // Columns t1, t2, d of the rotation frame of a framed node with director d (tests).
  Eigen::Matrix3d rotation_frame(int node, const Eigen::Vector3d& d) const { return frames_.frame(node, d); }
  const mesh::Mesh& mesh() const { return *mesh_; }
  int num_nodes() const { return mesh_->num_nodes(); }
  int num_elements() const { return mesh_->num_elements(); }
  double initial_thickness() const { return thickness_; }
  const element::ThicknessRule& thickness_rule() const { return rule_; }

  // f_ext(lambda) += lambda x amplitude on this DOF (forces N, moments N mm).
  void add_nodal_load(int dof, double amplitude);
  // Dead load per unit reference area (e.g. self-weight) on the given elements, as
  // consistent nodal forces (2x2 Gauss points on the bilinear geometry).
  void add_surface_load(const std::vector<int>& elements, const Eigen::Vector3d& load_per_area);
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
  int num_dofs() const override { return 6 * num_nodes(); }
  const std::vector<std::vector<int>>& element_dofs() const override { return element_dofs_; }
  solver::ElementEvaluation evaluate_element(int e, Eigen::VectorXd* re, Eigen::MatrixXd* ke) override;
  Eigen::VectorXd external_forces(double lambda) const override;
  void set_trial(const Eigen::VectorXd& delta, double alpha) override;
  void accept_trial() override;
  void commit(double lambda) override;
  void revert() override;
  Eigen::VectorXd increment_from_committed() const override;

  // Committed results.
  Eigen::Vector3d displacement(int node) const { return x_[static_cast<std::size_t>(node)] - mesh_->nodes[static_cast<std::size_t>(node)]; }
  const Eigen::Vector3d& position(int node) const { return x_[static_cast<std::size_t>(node)]; }
  const Eigen::Vector3d& director(int node) const { return d_[static_cast<std::size_t>(node)]; }
  const std::vector<Eigen::Vector3d>& positions() const { return x_; }
  const std::vector<Eigen::Vector3d>& directors() const { return d_; }
  const Eigen::Vector3d& reference_director(int node) const { return d0_[static_cast<std::size_t>(node)]; }
  double load_factor() const { return lambda_; }
  const element::ShellQ4& element(int e) const { return elements_[static_cast<std::size_t>(e)]; }
  // The corners' committed positions and directors of element e.
  void committed_corners(int e, element::NodeVectors* x, element::NodeVectors* d) const;
  // Rolling direction given to element e (ShellModelOptions::material_axes).
  const Eigen::Vector3d& material_axis(int e) const { return elements_[static_cast<std::size_t>(e)].options().material_axis; }
  // Committed thickness of element e (mean of its in-plane points) and of each node (mean of its elements).
  double element_thickness(int e) const;
  std::vector<double> nodal_thickness() const;
  double load_work() const { return load_work_; }  // work of the nodal loads so far [N mm]
  const std::vector<std::string>& warnings() const { return warnings_; }
  double max_thickness_over_length() const { return max_t_over_l_; }

  // Checkpoints (model_archive.hpp): the committed state is replaced and the iterate and trial
  // configurations reset to it. Sizes are the caller's to check.
  element::ShellQ4& element_state(int e) { return elements_[static_cast<std::size_t>(e)]; }
  void restore_committed(double lambda, std::vector<Eigen::Vector3d> x, std::vector<Eigen::Vector3d> d, double load_work);

 private:
  const mesh::Mesh* mesh_;
  ShellModelOptions options_;
  material::ReturnMapping<double, 3> law_;
  element::ThicknessRule rule_;
  double thickness_;
  std::vector<element::ShellQ4> elements_;
  std::vector<std::vector<int>> element_dofs_;
  std::vector<Eigen::Vector3d> d0_;
  std::vector<Eigen::Vector3d> x_, d_;            // committed
  std::vector<Eigen::Vector3d> xi_, di_;          // iterate
  std::vector<Eigen::Vector3d> xt_, dt_;          // trial
  Eigen::VectorXd increment_, increment_trial_;   // sum of accepted corrections in this increment
  std::vector<std::pair<int, double>> loads_;
  double lambda_ = 0.0;
  double load_work_ = 0.0;                        // committed work of the nodal loads [N mm]
  std::vector<std::string> warnings_;
  double max_t_over_l_ = 0.0;
  std::vector<std::unique_ptr<ElementContribution>> contributions_;
  NodalRotationFrames frames_;
  void check_geometry(const mesh::Mesh& mesh, double thickness);
  void build_directors_and_elements(const mesh::Mesh& mesh, double thickness);
};

}  // namespace spifit::model
