#include "forward/model/hanging_nodes.hpp"

#include "forward/model/shell_model.hpp"

#include <utility>
#include <vector>

namespace spifit::model {
namespace {

void tie_components(const mesh::Mesh& mesh, std::initializer_list<int> components, solver::DofConstraints* c) {
  for (const mesh::ConstrainedNode& h : mesh.constrained_nodes)
    for (int k : components) {
      std::vector<std::pair<int, double>> terms;
      for (const auto& [n, w] : h.masters) terms.emplace_back(ShellModel::dof(n, k), w);
      c->tie(ShellModel::dof(h.node, k), std::move(terms));
    }
}

}  // namespace

void tie_hanging_translations(const mesh::Mesh& mesh, solver::DofConstraints* c) { tie_components(mesh, {0, 1, 2}, c); }

void tie_hanging_rotations(const mesh::Mesh& mesh, solver::DofConstraints* c) { tie_components(mesh, {3, 4}, c); }

}  // namespace spifit::model
