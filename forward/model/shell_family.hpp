#pragma once
// The ShellQ4 element family (forward/element/shell_q4.hpp) over a mesh's quadrilaterals: six
// DOFs per node with nodal directors, the sheet's thickness checks against the element size,
// material axes fixed or polar, and the model's contributions (the tool's contact) evaluated in
// the shell's position-and-director variables, turned into nodal forces and moments once.
#include "forward/element/shell_q4.hpp"
#include "forward/material/return_mapping.hpp"
#include "forward/mesh/mesh.hpp"
#include "forward/model/element_family.hpp"

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

class ShellFamily final : public ElementFamily {
 public:
  // Throws std::invalid_argument for a mesh with hexahedra, a degenerate element (naming it),
  // t/l above the limit, an unsupported number of thickness points, or bad options. The family
  // must not move: its elements refer to its law and thickness rule.
  ShellFamily(const mesh::Mesh& mesh, double thickness, const material::MaterialParams<double>& material, const ShellModelOptions& options);
  ShellFamily(const ShellFamily&) = delete;
  ShellFamily& operator=(const ShellFamily&) = delete;

  std::string name() const override { return "shell"; }
  int dofs_per_node() const override { return 6; }
  int num_elements() const override { return static_cast<int>(elements_.size()); }
  std::vector<int> element_nodes(int e) const override;
  std::vector<Eigen::Vector3d> reference_directors() const override { return d0_; }
  solver::ElementEvaluation evaluate(int e, const ElementInputs& in, Eigen::VectorXd* re, Eigen::MatrixXd* ke) override;
  void commit() override;
  void revert() override;
  // Mean of the element's in-plane points' committed thickness.
  double element_thickness(int e) const override;
  const std::vector<std::string>& warnings() const override { return warnings_; }
  // Elastic, plastic and transverse-shear energies of the elements.
  void add_energies(const FeModel& model, ModelEnergies* energies) const override;
  // Point data: director, thickness (mean of the elements at the node); cell data: the largest
  // equivalent plastic strain through the element, and the in-plane stresses of the bottom,
  // middle and top layers (means over the in-plane points).
  void add_vtu_data(const FeModel& model, mesh::VtuFrame* frame) const override;
  void save_state(io::BinaryWriter& w) const override;
  void load_state(io::BinaryReader& r) override;
  // Both the 2 x 2 element and the one-point one.
  void enable_sensitivities(const material::MaterialParams<material::SensitivityScalar>& law, int count) override;
  solver::ElementEvaluation sensitivity_load(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, Eigen::MatrixXd* load) override;
  solver::ElementEvaluation update_sensitivities(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, const Eigen::MatrixXd& du,
                                                 Eigen::Matrix<double, 3, material::kSensitivitySlots>* contribution_force) override;
  material::SensitivityRow thickness_sensitivity(int e) const override { return 2.0 * offset_sensitivity(e); }
  bool tangent_was_exact() const override;
  void set_exact_tangents(bool exact) override;
  void save_sensitivities(io::BinaryWriter& w) const override;
  void load_sensitivities(io::BinaryReader& r) override;

  const element::ShellQ4& element(int e) const { return elements_[static_cast<std::size_t>(e)]; }
  element::ShellQ4& element(int e) { return elements_[static_cast<std::size_t>(e)]; }
  double initial_thickness() const { return thickness_; }
  const element::ThicknessRule& thickness_rule() const { return rule_; }
  double max_thickness_over_length() const { return max_t_over_l_; }

 private:
  const mesh::Mesh* mesh_;
  ShellModelOptions options_;
  material::ReturnMapping<double, 3> law_;
  element::ThicknessRule rule_;
  double thickness_;
  std::vector<element::ShellQ4> elements_;
  std::vector<Eigen::Vector3d> d0_;
  std::vector<std::string> warnings_;
  double max_t_over_l_ = 0.0;
  std::unique_ptr<element::SensLaw> sensitivity_law_;  // the law with derivative slots
  element::NarrowLaws narrow_laws_;                   // the same with fewer, when they suffice
  int sensitivity_count_ = 0;                          // the slots in use
  // The derivatives of the contributions' forces on element e (p-variables) and of the force on
  // the tool through it (ElementContribution::add_derivatives), from the committed DOFs'
  // derivatives du0 and the trial ones du (null: held fixed, the pseudo-load); false if none
  // touches it.
  bool contribution_derivatives(int e, const ElementInputs& in, const element::NodeVectors& x, const element::NodeVectors& d,
                                const element::SensDofs& du0, const element::SensDofs* du, element::SensDofs* drc,
                                Eigen::Matrix<double, 3, material::kSensitivitySlots>* tool_force) const;
  // d (h / 2) / d p of element e's committed thickness.
  material::SensitivityRow offset_sensitivity(int e) const;
  void check_geometry(const mesh::Mesh& mesh, double thickness);
  void build_directors_and_elements(const mesh::Mesh& mesh, double thickness);
};

// The corners' positions and directors of quadrilateral q, taken from node vectors xs, ds.
void corner_vectors(const mesh::Quad& q, const std::vector<Eigen::Vector3d>& xs, const std::vector<Eigen::Vector3d>& ds,
                    element::NodeVectors* x, element::NodeVectors* d);

}  // namespace spifit::model
