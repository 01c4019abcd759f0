#include "forward/model/hanging_nodes.hpp"

#include "forward/model/fe_model.hpp"

#include <utility>
#include <vector>

namespace spifit::model {
namespace {

void tie_components(const FeModel& model, const mesh::ConstrainedNode& h, std::initializer_list<int> components, solver::DofConstraints* c) {
  for (int k : components) {
    std::vector<std::pair<int, double>> terms;
    for (const auto& [n, w] : h.masters) terms.emplace_back(model.node_dof(n, k), w);
    c->tie(model.node_dof(h.node, k), std::move(terms));
  }
}

// An unframed master whose rotations about x and y are both free (or tied).
bool has_fixed_axis_rotations(const FeModel& model, int node, const solver::DofConstraints& c) {
  return !model.has_rotation_frame(node) && !c.prescribed(model.node_dof(node, 3)) && !c.prescribed(model.node_dof(node, 4));
}

}  // namespace

void tie_hanging_translations(const FeModel& model, solver::DofConstraints* c) {
  for (const mesh::ConstrainedNode& h : model.mesh().constrained_nodes) tie_components(model, h, {0, 1, 2}, c);
}

int tie_hanging_rotations(const FeModel& model, solver::DofConstraints* c) {
  int tied = 0;
  for (const mesh::ConstrainedNode& h : model.mesh().constrained_nodes) {
    if (model.node_dofs(h.node) != 6) continue;
    bool fixed_axes = false;
    if (model.has_rotation_frame(h.node))
      for (const auto& [n, w] : h.masters) fixed_axes = fixed_axes || has_fixed_axis_rotations(model, n, *c);
    if (fixed_axes) continue;
    tie_components(model, h, {3, 4}, c);
    ++tied;
  }
  return tied;
}

}  // namespace spifit::model
