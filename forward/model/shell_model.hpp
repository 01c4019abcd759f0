#pragma once
// A shell finite-element model: mesh, ShellQ4 elements, six DOFs per node (ux uy uz, then
// rotation increments about x y z, or in the node's frame: use_nodal_rotation_frames), nodal
// directors, concentrated loads, and the configuration bookkeeping the Newton solver needs
// (committed / iterate / trial).
#include "forward/contact/shell_contact.hpp"
#include "forward/element/shell_q4.hpp"
#include "forward/io/vtu_writer.hpp"
#include "forward/mesh/mesh.hpp"
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/nonlinear_problem.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace spifit::model {

struct ShellModelOptions {
  element::ShellOptions shell;
  double density = 2.7e-9;  // t/mm^3 (lumped mass)
  // Thickness over the shortest element edge (NUMERICS.md): a warning above warn_..., an
  // error above max_... (the thesis's fine cone mesh has t/l = 1.7).
  double warn_thickness_over_length = 1.0;
  double max_thickness_over_length = 3.0;
  // Material axes of the elements. `fixed` (default): the rolling direction is
  // shell.material_axis everywhere, as in a rolled sheet. `polar`: shell.material_axis is read in
  // each element's polar frame (e_r, e_theta, z) at its reference centroid, so the rolling
  // direction turns with the polar angle; the material is then the same in every pie of a disc,
  // which is what the cyclic ties of a pie model assume (docs/cone-scene.md, "Material axes").
  enum class MaterialAxes { fixed, polar };
  MaterialAxes material_axes = MaterialAxes::fixed;
};

// "fixed" or "polar"; false otherwise (the [sheet] material_axes key, summary.json).
bool material_axes_from_string(const std::string& s, ShellModelOptions::MaterialAxes* axes);
const char* to_string(ShellModelOptions::MaterialAxes axes);

// Energy account of the committed state [N mm] (SPEC §4: checks). Static implicit solution:
// no kinetic energy. external_work = the tool's (and its copies') work on the sheet, the
// trapezoidal sum over the increments of (f_old + f_new) / 2 . (change of the tool centre),
// plus the work of the nodal loads; a spinning tool's torque is not counted.
// contact_offset_release: the tool-side surface sits h/2 from the mid-surface with the
// committed thickness h; when h changes at a commit (constant-volume update) that surface
// moves under the loaded contact points and their penalty energy changes by about
// -(normal force) x (change of h/2) without any work: a plane-stress shell has no
// through-thickness stress to do that work. The balance
//   external_work = elastic + plastic + transverse_shear + contact_stored
//                   + friction_dissipation + contact_offset_release
// holds up to the trapezoidal rule's error (balance_error).
struct ModelEnergies {
  double external_work = 0.0, elastic = 0.0, plastic = 0.0, transverse_shear = 0.0;
  double contact_stored = 0.0, friction_dissipation = 0.0, contact_offset_release = 0.0, kinetic = 0.0;
  double internal() const { return elastic + plastic + transverse_shear; }
  double balance_error() const {
    return external_work - internal() - contact_stored - friction_dissipation - contact_offset_release - kinetic;
  }
};

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

  // Five unknowns per node (docs/numerics-shell.md, "Nodal rotation frames"). At every node
  // whose three rotations are free in c (neither prescribed, tied, nor the master of a tie),
  // the rotation unknowns 3, 4, 5 are taken in the frame (t1, t2, d) of the node's current
  // director d instead of about x, y, z, and the one about d -- the drilling rotation, which
  // moves no director and has only the tangent's regularising stiffness -- is prescribed to
  // zero in c, so it leaves the factorisation. The tangent's drilling rows and columns are
  // decoupled from everything else (ShellQ4), so the Newton iterates are those of the six-DOF
  // model up to round-off. Full DOF vectors the solver exchanges with the model (residuals,
  // corrections, increment_from_committed, external_forces) carry those nodes' rotation parts
  // in their frames; internal_forces() and all committed results stay in x, y, z. Call before
  // c.finalize() and the first solve. Returns the number of nodes with a frame.
  int use_nodal_rotation_frames(solver::DofConstraints* c);
  bool has_rotation_frame(int node) const { return !framed_.empty() && framed_[static_cast<std::size_t>(node)]; }
  // Columns t1, t2, d of the rotation frame of a node with director d (a frame carried from
  // the reference director by the shortest rotation onto d): exposed for tests.
  Eigen::Matrix3d rotation_frame(int node, const Eigen::Vector3d& d) const;
  const mesh::Mesh& mesh() const { return *mesh_; }
  int num_nodes() const { return mesh_->num_nodes(); }
  int num_elements() const { return mesh_->num_elements(); }

  // f_ext(lambda) += lambda x amplitude on this DOF (forces N, moments N mm).
  void add_nodal_load(int dof, double amplitude);
  // Dead load per unit reference area (e.g. self-weight) on the given elements, as
  // consistent nodal forces (2x2 Gauss points on the bilinear geometry).
  void add_surface_load(const std::vector<int>& elements, const Eigen::Vector3d& load_per_area);
  // Internal forces at the current iterate (full vector): reactions at supported DOFs.
  Eigen::VectorXd internal_forces();

  // Contact with a rigid sphere whose centre follows path(lambda) (tool travel as load factor).
  using ToolPathFunction = std::function<Eigen::Vector3d(double)>;
  // spin_per_load_factor: tool rotation about +z [rad] per unit of load factor (rpm x 2 pi / 60
  // x seconds per unit load factor); positive = counter-clockwise seen from above.
  void set_tool(double radius, ToolPathFunction path, const contact::ContactOptions& options, double spin_per_load_factor = 0.0);
  // Virtual tools of a pie model with cyclic ties (thesis Fig. 8.4): the contact also sees
  // copies of the tool rotated about z by these angles [deg], typically {+gamma, -gamma}, so
  // that a footprint crossing one pie edge acts on the other. Each copy keeps its own contact
  // point states (friction history). Call after set_tool and before the first increment (the
  // contact states are reset); an empty list removes the copies. Angles must be finite and
  // not multiples of 360.
  void set_tool_copies(const std::vector<double>& angles_deg);
  const std::vector<double>& tool_copies_deg() const { return copies_deg_; }
  bool has_tool() const { return contact_ != nullptr; }
  const contact::SphereTool& tool() const { return tools_.front(); }  // the real tool
  // Committed contact (zero without a tool): penetration and pressure are the largest over the
  // real tool and its copies; force_on_sheet is the force the REAL tool exerts on the (cyclic)
  // sheet: the real tool's own contact plus each copy's contact rotated back by the copy's
  // angle (see shell_model.cpp). Without copies: the plain sum over the contact points.
  contact::ContactSummary contact_summary() const;
  // Largest penetration of any tool into the committed tool-side surface, sampled over every
  // element near a tool (ShellContact::surface_penetration) and never below the contact
  // points' own: the depth the tool reaches, against contact_summary().max_penetration, the
  // depth the points feel. 0 without contact.
  double surface_penetration() const;
  // Committed contact of tool i alone (0: the real tool; i >= 1: copy i - 1 of
  // tool_copies_deg()), in the sheet's frame (not rotated back).
  contact::ContactSummary contact_summary_of_tool(int i) const;
  // Force exerted BY the sheet ON the (real) tool (SPEC §1), committed state.
  Eigen::Vector3d tool_force() const { return -contact_summary().force_on_sheet; }

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

  // Committed state for checkpoints (forward/io/binary_archive.hpp), bit-exact: load factor,
  // nodal positions and directors, every element's sections, the real tool and its copies,
  // and the contact point states of each. load_state needs a model built the same way (mesh,
  // thickness points, set_tool and set_tool_copies called); the iterate and trial
  // configurations are reset to the committed one. io::ArchiveError on any size mismatch.
  void save_state(io::BinaryWriter& w) const;
  void load_state(io::BinaryReader& r);

  // Committed results.
  Eigen::Vector3d displacement(int node) const { return x_[static_cast<std::size_t>(node)] - mesh_->nodes[static_cast<std::size_t>(node)]; }
  const Eigen::Vector3d& position(int node) const { return x_[static_cast<std::size_t>(node)]; }
  const Eigen::Vector3d& director(int node) const { return d_[static_cast<std::size_t>(node)]; }
  const Eigen::Vector3d& reference_director(int node) const { return d0_[static_cast<std::size_t>(node)]; }
  double load_factor() const { return lambda_; }
  const element::ShellQ4& element(int e) const { return elements_[static_cast<std::size_t>(e)]; }
  // Rolling direction given to element e (ShellModelOptions::material_axes).
  const Eigen::Vector3d& material_axis(int e) const { return elements_[static_cast<std::size_t>(e)].options().material_axis; }
  std::vector<double> nodal_thickness() const;
  ModelEnergies energies() const;
  // Lumped mass per node, Jetteur's diagonal matrix (thesis eqs. 6.61-6.62): translational
  // m_I (area share x thickness x density); rotational about the in-plane axes c m_I with
  // c = max(t^2/12, S/18) (bending and membrane frequencies of a rectangular sheet, S the
  // element area); about the normal (drilling) twice that.
  struct LumpedMass {
    std::vector<double> translational, rotational, drilling;
  };
  LumpedMass lumped_mass() const;
  io::VtuFrame vtu_frame() const;
  const std::vector<std::string>& warnings() const { return warnings_; }
  double max_thickness_over_length() const { return max_t_over_l_; }

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
  std::vector<std::string> warnings_;
  double max_t_over_l_ = 0.0;
  std::unique_ptr<contact::ShellContact> contact_;
  ToolPathFunction tool_path_;
  std::vector<contact::SphereTool> tools_{1};   // [0] the real tool, then its rotated copies
  std::vector<double> copies_deg_;
  std::vector<Eigen::Matrix3d> copy_rotations_{Eigen::Matrix3d::Identity()};  // one per tool: [0] = identity
  double spin_per_load_factor_ = 0.0;
  double tool_work_ = 0.0, load_work_ = 0.0;  // committed external work [N mm] (ModelEnergies)
  double offset_release_ = 0.0;                // ModelEnergies::contact_offset_release [N mm]
  std::vector<char> framed_;               // per node: rotation unknowns in the nodal frame
  std::vector<Eigen::Vector3d> frame_t1_;  // per node: t1 of the frame of the reference director
  // In place, on a full DOF vector: the rotation parts of framed nodes from x, y, z to the
  // frames of the directors ds (to_frame) or back.
  void rotate_to_frames(const std::vector<Eigen::Vector3d>& ds, bool to_frame, Eigen::VectorXd* v) const;
  // Moves the real tool and its copies (rotated centres and spin).
  void place_tools(const Eigen::Vector3d& centre_committed, const Eigen::Vector3d& centre, const Eigen::Vector3d& spin);
  double element_thickness(int e) const;
};

}  // namespace spifit::model
