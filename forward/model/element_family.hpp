#pragma once
// An element family of the FE model (fe_model.hpp): the elements of one kind over the mesh's
// cells of one type, with their node layout (6 DOFs per node, displacement and rotation with a
// director, for a shell; 3, displacement, for a solid), their material states and their
// evaluation. The model owns the nodal configurations and the bookkeeping the solver needs
// (committed / iterate / trial), the family everything per element: adding an element family
// means implementing this interface in the element's folder and registering it, nothing above.
#include "forward/material/sensitivity_scalar.hpp"
#include "forward/solver/nonlinear_problem.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::mesh {
struct Mesh;
struct VtuFrame;
}  // namespace spifit::mesh

namespace spifit::model {

class ElementContribution;
class FeModel;
struct ModelEnergies;
class NodalRotationFrames;

// What an element sees when it is evaluated: the nodal positions and directors of the trial
// configuration and of the committed one (the start of the increment; element states are
// integrated from it), and the model's additive contributions (the tool's contact), which the
// family evaluates in its own kinematic variables. Directors are meaningful at nodes with
// rotation DOFs only, and so are the nodal rotation frames (rotation_frames.hpp), in which a
// family with rotations returns the rotation rows and columns of framed nodes.
struct ElementInputs {
  const std::vector<Eigen::Vector3d>& x;
  const std::vector<Eigen::Vector3d>& d;
  const std::vector<Eigen::Vector3d>& x0;
  const std::vector<Eigen::Vector3d>& d0;
  const std::vector<std::unique_ptr<ElementContribution>>& contributions;
  const NodalRotationFrames& frames;
};

// The surface the model's contributions act on (the tool's contact).
struct ContactSurface {
  // Quadrilateral faces over the model's nodes, taken as they are (a solid's top faces); null:
  // the model mesh's own quadrilaterals, offset by half the element's thickness along the
  // directors (the shell's tool-side surface).
  const mesh::Mesh* faces = nullptr;
  std::vector<int> element;  // the model element of each face (with faces)
};

// The sheet's mid-surface at the model's committed state, one entry per mid-surface node: its
// top (tool-side) and bottom surfaces are current +- thickness / 2 along the unit director.
struct MidSurface {
  std::vector<Eigen::Vector3d> reference, current;
  std::vector<Eigen::Vector3d> director;  // a shell node's director; a solid column's bottom-to-top unit vector
  std::vector<double> thickness;          // the sheet's thickness there [mm]
};

// MidSurface's derivatives with respect to a run's parameters (after enable_sensitivities): per
// mid-surface node the current position's (3 x parameters), and the thickness's (a row per node).
struct MidSurfaceSensitivity {
  std::vector<Eigen::Matrix<double, 3, Eigen::Dynamic>> current;
  Eigen::MatrixXd thickness;
};

class ElementFamily {
 public:
  virtual ~ElementFamily() = default;
  // "shell", "brick", "solid_shell": for checkpoints and messages.
  virtual std::string name() const = 0;
  // DOFs at each node of the family's elements: 6 (ux uy uz, then rotation increments about x
  // y z, moving the node's director) or 3 (ux uy uz).
  virtual int dofs_per_node() const = 0;
  virtual int num_elements() const = 0;
  // Nodes of element e in the order of its residual (the mesh cell's order).
  virtual std::vector<int> element_nodes(int e) const = 0;
  // Where the contributions act; a family with faces passes each contribution, for an element
  // that has one, the face's index and corners (ElementContribution::add) with no offset.
  // std::invalid_argument when the family has no surface a tool could touch.
  virtual ContactSurface contact_surface() const { return {}; }
  // Reference directors of every node of the mesh (a family with rotation DOFs), else empty.
  virtual std::vector<Eigen::Vector3d> reference_directors() const { return {}; }
  // Residual (internal forces minus the contributions' external ones) and tangent of element e
  // at the trial configuration, dofs_per_node() values per node in element_nodes(e) order
  // (rotations about x y z, or in the frames of framed nodes); ke may be null. Called concurrently for distinct e; the element's
  // trial state is what commit() keeps.
  virtual solver::ElementEvaluation evaluate(int e, const ElementInputs& in, Eigen::VectorXd* re, Eigen::MatrixXd* ke) = 0;
  virtual void commit() = 0;  // every element's trial state becomes its committed state
  virtual void revert() = 0;  // every element's trial state is reset to its committed state
  // Committed thickness of element e [mm] (the sheet's, through this element).
  virtual double element_thickness(int e) const = 0;
  // Remarks on the mesh the family accepted (e.g. t/l above what the shell is good for).
  virtual const std::vector<std::string>& warnings() const = 0;
  // Adds the elements' stored and dissipated energies at the model's committed state
  // (model_energies.hpp).
  virtual void add_energies(const FeModel& model, ModelEnergies* energies) const = 0;
  // The family's point and cell data of the model's committed state for the VTU output, appended
  // after the model's displacement (model_vtu.hpp).
  virtual void add_vtu_data(const FeModel& model, mesh::VtuFrame* frame) const = 0;
  // The sections' view of the sheet. By default the model's nodes with their directors and
  // FeModel::nodal_thickness (a shell's nodes lie on its mid-surface).
  virtual MidSurface mid_surface(const FeModel& model) const;
  // Its derivatives: by default the model's nodes' (FeModel::position_sensitivity) and
  // FeModel::nodal_thickness_sensitivity.
  virtual MidSurfaceSensitivity mid_surface_sensitivity(const FeModel& model) const;
  // Direct differentiation (docs/design/sensitivities.md), at the trial configuration of the
  // converged iterate. enable_sensitivities: the elements keep their committed states'
  // derivatives with respect to the parameters seeded in `law` (the family's material with
  // derivative slots); std::invalid_argument (the reason) where the family or its options have
  // none. sensitivity_load: element e's pseudo-load, the residual's derivative with respect to
  // each slot at fixed DOFs (through the law, the committed state's derivatives and the
  // contributions' dependence on the element's thickness, the committed DOFs' derivatives du0
  // and their own history), in evaluate()'s DOF order, rotations about x, y, z.
  // update_sensitivities: the elements' and contributions' trial derivatives from the DOFs'
  // derivatives du (same layout), kept by commit(); *contribution_force (if not null) receives
  // the derivative of the sum of the contributions' forces on the element's nodes (rows x, y,
  // z; the residual's sign: the force the sheet exerts on the tool).
  virtual void enable_sensitivities(const material::MaterialParams<material::SensitivityScalar>& law, int count);
  virtual solver::ElementEvaluation sensitivity_load(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, Eigen::MatrixXd* load);
  virtual solver::ElementEvaluation update_sensitivities(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, const Eigen::MatrixXd& du,
                                                         Eigen::Matrix<double, 3, material::kSensitivitySlots>* contribution_force);
  // Whether the last evaluation's tangents were the residual's exact derivative, and the switch
  // to exact ones (solver::NonlinearProblem::tangent_was_exact); exact by default.
  virtual bool tangent_was_exact() const { return true; }
  virtual void set_exact_tangents(bool exact) { (void)exact; }
  // The committed derivative of element_thickness(e) (after enable_sensitivities).
  virtual material::SensitivityRow thickness_sensitivity(int e) const;
  // Committed element states, bit-exact (checkpoints); io::ArchiveError on a mismatch.
  virtual void save_state(io::BinaryWriter& w) const = 0;
  virtual void load_state(io::BinaryReader& r) = 0;
  // Their committed derivatives, after enable_sensitivities (checkpoints of a run with
  // sensitivities); load_sensitivities resets the trial derivatives to them.
  virtual void save_sensitivities(io::BinaryWriter& w) const;
  virtual void load_sensitivities(io::BinaryReader& r);
};

}  // namespace spifit::model
