#pragma once
// The solid families over a mesh's hexahedra: three DOFs per node, one solid element per
// hexahedron with its material axes (the rolling direction fixed, or read in the polar frame,
// turned into the plane of the sheet at the element), and the sheet thickness through each
// element's column of layers. The elements are one-point bricks (element/brick8.hpp) in any
// number of layers, or solid-shells (element/solid_shell8.hpp), one through the thickness with
// the shell's thickness rule along it. The elements of a solid sheet are those of
// mesh::extrude_sheet: layer l of mid-surface element q is element l m + q (m elements per
// layer).
#include "forward/element/brick8.hpp"
#include "forward/element/solid_element.hpp"
#include "forward/element/solid_shell8.hpp"
#include "forward/element/thickness_rule.hpp"
#include "forward/mesh/face_surface.hpp"
#include "forward/mesh/mesh.hpp"
#include "forward/model/element_family.hpp"
#include "forward/model/shell_family.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spifit::model {

enum class SolidElementKind { brick, solid_shell };

struct SolidOptions {
  SolidElementKind element = SolidElementKind::brick;
  // The rolling direction (material axis 1), projected into each element's sheet plane; the
  // sheet normal of an element runs from its bottom face (corners 0-3) to its top face (4-7).
  Eigen::Vector3d material_axis = Eigen::Vector3d::UnitX();
  ShellModelOptions::MaterialAxes material_axes = ShellModelOptions::MaterialAxes::fixed;
  // The bricks' hourglass stabilisation (element::Brick8): factor 1 on the centre's tangent by
  // default.
  element::HourglassOptions hourglass;
  // The solid-shells' integration points through the thickness, and their enhanced strains'
  // tolerance (element::SolidShell8).
  element::ThicknessRule thickness_rule = element::gauss_legendre_rule(5);
  double enhanced_tolerance = element::SolidShell8::kDefaultEnhancedTolerance;
  // Elements through the thickness (mesh::extrude_sheet's layers; 1 for solid-shells).
  int layers = 1;
};

class SolidFamily final : public ElementFamily {
 public:
  // Throws std::invalid_argument for a mesh with quadrilaterals or without hexahedra, an
  // element count that is not a multiple of the layers, solid-shells in more than one layer, an
  // inverted element or a rolling direction along an element's normal (naming the element).
  SolidFamily(const mesh::Mesh& mesh, const material::MaterialParams<double>& material, const SolidOptions& options);
  SolidFamily(const SolidFamily&) = delete;
  SolidFamily& operator=(const SolidFamily&) = delete;

  // "brick" or "solid_shell".
  std::string name() const override;
  int dofs_per_node() const override { return 3; }
  int num_elements() const override { return static_cast<int>(elements_.size()); }
  std::vector<int> element_nodes(int e) const override;
  // The sheet's top faces (the mesh's face set "top", mesh::extrude_sheet's tool side):
  // std::invalid_argument when the mesh has none.
  ContactSurface contact_surface() const override;
  // The contributions act on the top face of an element that has one (no offset: the face is
  // the sheet's surface), their forces on its four top corners.
  solver::ElementEvaluation evaluate(int e, const ElementInputs& in, Eigen::VectorXd* re, Eigen::MatrixXd* ke) override;
  void commit() override;
  void revert() override;
  // The committed thickness of the sheet through element e: the sum over its column of each
  // layer's reference height times its thickness ratio (Brick8::thickness_ratio).
  double element_thickness(int e) const override;
  const std::vector<std::string>& warnings() const override { return warnings_; }
  // Elastic (with the bricks' hourglass stabilisation's work) and plastic work.
  void add_energies(const FeModel& model, ModelEnergies* energies) const override;
  // Cell data: equivalent plastic strain (the largest over the element's points), sheet
  // thickness, the Kirchhoff stress along the three material axes (the element's volume
  // average), and for bricks the work of the hourglass forces [N mm].
  void add_vtu_data(const FeModel& model, mesh::VtuFrame* frame) const override;
  // Each node column's midpoint (reference and current) and the distance between its bottom and
  // top nodes (mesh::extrude_sheet's columns: node k n + i at level k).
  MidSurface mid_surface(const FeModel& model) const override;
  // Its derivatives: the midpoint's and the distance's, from the column's two end nodes.
  MidSurfaceSensitivity mid_surface_sensitivity(const FeModel& model) const override;
  void save_state(io::BinaryWriter& w) const override;
  void load_state(io::BinaryReader& r) override;
  // Direct differentiation (docs/design/sensitivities.md, "Solids"), through the elements'
  // (element::SolidElement) and the contributions on their top faces.
  void enable_sensitivities(const material::MaterialParams<material::SensitivityScalar>& law, int count) override;
  solver::ElementEvaluation sensitivity_load(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, Eigen::MatrixXd* load) override;
  solver::ElementEvaluation update_sensitivities(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, const Eigen::MatrixXd& du,
                                                 Eigen::Matrix<double, 3, material::kSensitivitySlots>* contribution_force) override;
  material::SensitivityRow thickness_sensitivity(int e) const override;
  // Points that started the increment at rest (element::SolidPoint::tangent_was_exact).
  bool tangent_was_exact() const override;
  void set_exact_tangents(bool exact) override;
  void save_sensitivities(io::BinaryWriter& w) const override;
  void load_sensitivities(io::BinaryReader& r) override;

  const element::SolidElement& element(int e) const { return *elements_[static_cast<std::size_t>(e)]; }
  // Element e as a brick or a solid-shell: std::logic_error for the other kind.
  const element::Brick8& brick(int e) const;
  const element::SolidShell8& solid_shell(int e) const;
  SolidElementKind kind() const { return kind_; }
  int layers() const { return layers_; }

 private:
  const mesh::Mesh* mesh_;
  element::SolidPoint::Law law_;
  SolidElementKind kind_;
  int layers_;
  std::vector<std::unique_ptr<element::SolidElement>> elements_;
  std::vector<double> height0_;  // reference distance between the bottom and top face centroids
  mesh::FaceSurface top_;        // the top faces (empty without a face set "top")
  std::vector<int> face_of_element_;  // index into top_ (-1: no top face)
  std::vector<std::string> warnings_;
  int sensitivity_count_ = 0;
  std::unique_ptr<element::SolidSensitivityLaw> sensitivity_law_;
  // The contributions' derivatives on element e's top face (if it has one): their pseudo-load
  // (du null) or their trial derivatives (du given), added to *load's rows of the face's
  // corners, and the derivative of their force on the tool.
  bool contribution_derivatives(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, const Eigen::MatrixXd* du, element::HexSensitivities* load,
                                Eigen::Matrix<double, 3, material::kSensitivitySlots>* tool_force) const;
};

}  // namespace spifit::model
