#include "forward/model/shell_model.hpp"

#include <cmath>
#include <utility>

namespace spifit::model {

ShellModel::ShellModel(const mesh::Mesh& mesh, double thickness, const material::MaterialParams<double>& material,
                       const ShellModelOptions& options)
    : FeModel(mesh, std::make_unique<ShellFamily>(mesh, thickness, material, options)) {}

void ShellModel::add_surface_load(const std::vector<int>& elements, const Eigen::Vector3d& load_per_area) {
  const double g = 1.0 / std::sqrt(3.0);
  for (int e : elements) {
    const auto& q = mesh().quads.at(static_cast<std::size_t>(e));
    element::NodeVectors X;
    for (std::size_t i = 0; i < 4; ++i) X[i] = mesh().nodes[static_cast<std::size_t>(q[i])];
    for (int p = 0; p < 4; ++p) {
      const double xi = element::kNodeXi[p] * g, eta = element::kNodeEta[p] * g;
      const Eigen::Vector4d n = element::quad_shape(xi, eta);
      const double da = element::quad_area_jacobian(X, xi, eta);
      for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c)
          if (load_per_area(c) != 0.0) loads().emplace_back(dof(q[static_cast<std::size_t>(i)], c), n(i) * da * load_per_area(c));
    }
  }
}

void ShellModel::committed_corners(int e, element::NodeVectors* x, element::NodeVectors* d) const {
  corner_vectors(mesh().quads[static_cast<std::size_t>(e)], positions(), directors(), x, d);
}

}  // namespace spifit::model
