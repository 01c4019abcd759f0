#include "forward/model/cyclic_symmetry.hpp"

#include "forward/model/fe_model.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace spifit::model {

void tie_cyclic_edges(const FeModel& model, const std::string& master_set, const std::string& slave_set, double angle_deg,
                      solver::DofConstraints* c, double tol) {
  const mesh::Mesh& m = model.mesh();
  const auto find = [&](const std::string& name) -> const std::vector<int>& {
    const auto it = m.node_sets.find(name);
    if (it == m.node_sets.end()) throw std::invalid_argument("cyclic symmetry: no node set \"" + name + "\"");
    return it->second;
  };
  const std::vector<int>& masters = find(master_set);
  const std::vector<int>& slaves = find(slave_set);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(angle_deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  double scale = 0.0;
  for (const auto& p : m.nodes) scale = std::max(scale, p.norm());
  for (int mi : masters) {
    const Eigen::Vector3d& pm = m.nodes[static_cast<std::size_t>(mi)];
    const Eigen::Vector3d target = R * pm;
    int partner = -1;
    for (int si : slaves)
      if ((m.nodes[static_cast<std::size_t>(si)] - target).norm() <= tol * std::max(scale, 1.0)) partner = si;
    if (partner < 0) throw std::invalid_argument("cyclic symmetry: node " + std::to_string(mi) + " of " + master_set + " has no partner in " + slave_set);
    if (partner == mi) {  // on the axis: the DOFs must equal their own rotation
      if (std::abs(std::remainder(angle_deg, 360.0)) > 1e-12)
        for (int k : {0, 1, 3, 4})
          if (k < model.node_dofs(mi)) c->prescribe(model.node_dof(mi, k));
      continue;
    }
    for (int block = 0; block < model.node_dofs(mi) / 3; ++block)
      for (int i = 0; i < 3; ++i) {
        std::vector<std::pair<int, double>> terms;
        for (int j = 0; j < 3; ++j)
          if (R(i, j) != 0.0 && std::abs(R(i, j)) > 1e-15) terms.emplace_back(model.node_dof(mi, 3 * block + j), R(i, j));
        c->tie(model.node_dof(partner, 3 * block + i), std::move(terms));
      }
  }
}

}  // namespace spifit::model
