#pragma once
// A shell finite-element model: the FE model (fe_model.hpp) over the ShellQ4 family
// (shell_family.hpp) of a quadrilateral mesh, six DOFs per node, with the shell's accessors:
// elements and their sections, thickness rule and initial thickness, material axes, and dead
// surface loads on quadrilaterals.
#include "forward/model/fe_model.hpp"
#include "forward/model/shell_family.hpp"

namespace spifit::model {

class ShellModel final : public FeModel {
 public:
  // Throws std::invalid_argument for a degenerate element (naming it), t/l above the limit,
  // an unsupported number of thickness points, or bad options.
  ShellModel(const mesh::Mesh& mesh, double thickness, const material::MaterialParams<double>& material,
             const ShellModelOptions& options);

  static int dof(int node, int component) { return 6 * node + component; }
  const ShellFamily& shell() const { return static_cast<const ShellFamily&>(family()); }
  double initial_thickness() const { return shell().initial_thickness(); }
  const element::ThicknessRule& thickness_rule() const { return shell().thickness_rule(); }

  // Dead load per unit reference area (e.g. self-weight) on the given elements, as
  // consistent nodal forces (2x2 Gauss points on the bilinear geometry).
  void add_surface_load(const std::vector<int>& elements, const Eigen::Vector3d& load_per_area);

  const element::ShellQ4& element(int e) const { return shell().element(e); }
  // The corners' committed positions and directors of element e.
  void committed_corners(int e, element::NodeVectors* x, element::NodeVectors* d) const;
  // Rolling direction given to element e (ShellModelOptions::material_axes).
  const Eigen::Vector3d& material_axis(int e) const { return element(e).options().material_axis; }
  double max_thickness_over_length() const { return shell().max_thickness_over_length(); }
};

}  // namespace spifit::model
