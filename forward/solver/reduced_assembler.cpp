#include "forward/solver/reduced_assembler.hpp"

#include <algorithm>

namespace spifit::solver {

ReducedAssembler::ReducedAssembler(const DofConstraints& constraints, const std::vector<std::vector<int>>& element_dofs)
    : constraints_(&constraints), element_dofs_(&element_dofs) {
  const std::size_t ne = element_dofs.size();
  reduced_dofs_.resize(ne);
  expansion_.resize(ne);
  direct_.resize(ne);
  has_ties_.assign(ne, 0);
  for (std::size_t e = 0; e < ne; ++e) {
    std::vector<int>& red = reduced_dofs_[e];
    for (int dof : element_dofs[e]) {
      if (constraints.tied(dof)) has_ties_[e] = 1;
      for (const auto& t : constraints.expansion(dof)) red.push_back(t.reduced);
    }
    std::sort(red.begin(), red.end());
    red.erase(std::unique(red.begin(), red.end()), red.end());
    const auto position = [&](int r) { return static_cast<int>(std::lower_bound(red.begin(), red.end(), r) - red.begin()); };
    const int k = static_cast<int>(element_dofs[e].size());
    if (has_ties_[e]) {
      Eigen::MatrixXd s = Eigen::MatrixXd::Zero(k, static_cast<Eigen::Index>(red.size()));
      for (int i = 0; i < k; ++i)
        for (const auto& t : constraints.expansion(element_dofs[e][static_cast<std::size_t>(i)])) s(i, position(t.reduced)) += t.coefficient;
      expansion_[e] = std::move(s);
    } else {
      direct_[e].assign(static_cast<std::size_t>(k), -1);
      for (int i = 0; i < k; ++i) {
        const auto ex = constraints.expansion(element_dofs[e][static_cast<std::size_t>(i)]);
        if (!ex.empty()) direct_[e][static_cast<std::size_t>(i)] = position(ex[0].reduced);
      }
    }
  }
  pattern_ = build_pattern(constraints.num_reduced(), reduced_dofs_);
  map_ = build_assembly_map(pattern_, reduced_dofs_);
}

void ReducedAssembler::add(int e, const Eigen::VectorXd& re, const Eigen::MatrixXd* ke, const Eigen::VectorXd* dg_local,
                           Eigen::VectorXd* r_bar, SparseMatrix* k_bar) const {
  const auto ue = static_cast<std::size_t>(e);
  const std::vector<int>& red = reduced_dofs_[ue];
  const auto m = red.size();
  // The residual part only when asked for (the Newton solver scatters residuals itself).
  Eigen::VectorXd r;
  if (r_bar) {
    r = re;
    if (dg_local && ke && dg_local->size() > 0) r.noalias() += (*ke) * (*dg_local);
  }
  const std::vector<long>& pos = map_.positions[ue];
  if (has_ties_[ue]) {
    const Eigen::MatrixXd& s = expansion_[ue];
    if (r_bar) {
      const Eigen::VectorXd rr = s.transpose() * r;
      for (std::size_t i = 0; i < m; ++i) (*r_bar)(red[i]) += rr(static_cast<Eigen::Index>(i));
    }
    if (k_bar && ke) {
      const Eigen::MatrixXd kk = s.transpose() * (*ke) * s;
      auto& v = k_bar->values();
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < m; ++j) v[static_cast<std::size_t>(pos[i * m + j])] += kk(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    }
    return;
  }
  const std::vector<int>& dir = direct_[ue];
  const std::size_t k = dir.size();
  if (r_bar)
    for (std::size_t i = 0; i < k; ++i)
      if (dir[i] >= 0) (*r_bar)(red[static_cast<std::size_t>(dir[i])]) += r(static_cast<Eigen::Index>(i));
  if (k_bar && ke) {
    auto& v = k_bar->values();
    for (std::size_t i = 0; i < k; ++i) {
      if (dir[i] < 0) continue;
      const std::size_t row = static_cast<std::size_t>(dir[i]) * m;
      for (std::size_t j = 0; j < k; ++j)
        if (dir[j] >= 0) v[static_cast<std::size_t>(pos[row + static_cast<std::size_t>(dir[j])])] += (*ke)(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    }
  }
}

void ReducedAssembler::add_tangent_rows(int e, const Eigen::MatrixXd& ke, int row_begin, int row_end, SparseMatrix* k_bar) const {
  const auto ue = static_cast<std::size_t>(e);
  const std::vector<int>& red = reduced_dofs_[ue];
  const auto m = red.size();
  const std::vector<long>& pos = map_.positions[ue];
  auto& v = k_bar->values();
  const auto owned = [&](std::size_t local) { return red[local] >= row_begin && red[local] < row_end; };
  if (has_ties_[ue]) {
    bool any = false;
    for (std::size_t i = 0; i < m && !any; ++i) any = owned(i);
    if (!any) return;
    const Eigen::MatrixXd& s = expansion_[ue];
    const Eigen::MatrixXd kk = s.transpose() * ke * s;
    for (std::size_t i = 0; i < m; ++i)
      if (owned(i))
        for (std::size_t j = 0; j < m; ++j) v[static_cast<std::size_t>(pos[i * m + j])] += kk(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    return;
  }
  const std::vector<int>& dir = direct_[ue];
  const std::size_t k = dir.size();
  for (std::size_t i = 0; i < k; ++i) {
    if (dir[i] < 0 || !owned(static_cast<std::size_t>(dir[i]))) continue;
    const std::size_t row = static_cast<std::size_t>(dir[i]) * m;
    for (std::size_t j = 0; j < k; ++j)
      if (dir[j] >= 0) v[static_cast<std::size_t>(pos[row + static_cast<std::size_t>(dir[j])])] += ke(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  }
}

}  // namespace spifit::solver
