#include "forward/solver/dof_constraints.hpp"

#include <cmath>
#include <stdexcept>

namespace spifit::solver {

DofConstraints::DofConstraints(int num_dofs)
    : kind_(static_cast<std::size_t>(num_dofs), Kind::free), amplitude_(static_cast<std::size_t>(num_dofs), 0.0),
      masters_(static_cast<std::size_t>(num_dofs)) {}

void DofConstraints::check_dof(int dof, const char* what) const {
  if (dof < 0 || dof >= num_dofs())
    throw std::invalid_argument(std::string("inconsistent constraint: ") + what + " DOF " + std::to_string(dof) +
                                " out of range (" + std::to_string(num_dofs()) + " DOFs)");
}

void DofConstraints::prescribe(int dof, double amplitude) {
  check_dof(dof, "prescribed");
  auto& k = kind_[static_cast<std::size_t>(dof)];
  double& a = amplitude_[static_cast<std::size_t>(dof)];
  if (k == Kind::tied) throw std::invalid_argument("inconsistent constraint: DOF " + std::to_string(dof) + " is tied and prescribed");
  if (k == Kind::prescribed && a != amplitude)
    throw std::invalid_argument("inconsistent constraint: DOF " + std::to_string(dof) + " prescribed to " + std::to_string(a) +
                                " and to " + std::to_string(amplitude));
  k = Kind::prescribed;
  a = amplitude;
  finalized_ = false;
}

void DofConstraints::tie(int slave, std::vector<std::pair<int, double>> masters) {
  check_dof(slave, "tied");
  auto& k = kind_[static_cast<std::size_t>(slave)];
  if (k == Kind::prescribed) throw std::invalid_argument("inconsistent constraint: DOF " + std::to_string(slave) + " is prescribed and tied");
  if (k == Kind::tied) throw std::invalid_argument("inconsistent constraint: DOF " + std::to_string(slave) + " is tied twice");
  for (const auto& [m, c] : masters) {
    check_dof(m, "master");
    if (m == slave) throw std::invalid_argument("inconsistent constraint: DOF " + std::to_string(slave) + " is tied to itself");
    if (!std::isfinite(c)) throw std::invalid_argument("inconsistent constraint: non-finite coefficient for DOF " + std::to_string(slave));
  }
  k = Kind::tied;
  masters_[static_cast<std::size_t>(slave)] = std::move(masters);
  finalized_ = false;
}

// A tied DOF's expansion into reduced unknowns and its prescribed part per unit load factor,
// through tied masters (chains such as a hanging node whose edge ends on a pie's tied edge).
// Terms on the same reduced unknown are summed, in the order of their first appearance.
void DofConstraints::expand_tied(std::size_t i, const std::vector<int>& reduced, std::vector<int>& state,
                                 std::vector<std::vector<Term>>& expanded) {
  if (state[i] == 2) return;
  if (state[i] == 1)
    throw std::invalid_argument("inconsistent constraint: DOF " + std::to_string(i) + " is tied to itself through a chain of ties");
  state[i] = 1;
  std::vector<Term> out;
  auto add = [&out](int r, double c) {
    if (c == 0.0) return;
    for (Term& t : out)
      if (t.reduced == r) {
        t.coefficient += c;
        return;
      }
    out.push_back({r, c});
  };
  amplitude_[i] = 0.0;
  for (const auto& [m, c] : masters_[i]) {
    const auto mi = static_cast<std::size_t>(m);
    switch (kind_[mi]) {
      case Kind::free: add(reduced[mi], c); break;
      case Kind::prescribed: amplitude_[i] += c * amplitude_[mi]; break;
      case Kind::tied:
        expand_tied(mi, reduced, state, expanded);
        amplitude_[i] += c * amplitude_[mi];
        for (const Term& t : expanded[mi]) add(t.reduced, c * t.coefficient);
        break;
    }
  }
  expanded[i] = std::move(out);
  state[i] = 2;
}

void DofConstraints::finalize() {
  const std::size_t n = kind_.size();
  std::vector<int> reduced(n, -1);
  num_reduced_ = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (kind_[i] == Kind::free) reduced[i] = num_reduced_++;
  std::vector<int> state(n, 0);  // tied DOFs: 0 not expanded, 1 being expanded, 2 done
  std::vector<std::vector<Term>> expanded(n);
  for (std::size_t i = 0; i < n; ++i)
    if (kind_[i] == Kind::tied) expand_tied(i, reduced, state, expanded);
  offset_.assign(n + 1, 0);
  terms_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (kind_[i] == Kind::free) terms_.push_back({reduced[i], 1.0});
    else if (kind_[i] == Kind::tied) terms_.insert(terms_.end(), expanded[i].begin(), expanded[i].end());
    offset_[i + 1] = static_cast<long>(terms_.size());
  }
  finalized_ = true;
}

void DofConstraints::require_finalized() const {
  if (!finalized_) throw std::logic_error("DofConstraints used before finalize() (or changed after it)");
}

std::span<const DofConstraints::Term> DofConstraints::expansion(int dof) const {
  require_finalized();
  const auto i = static_cast<std::size_t>(dof);
  return {terms_.data() + offset_[i], static_cast<std::size_t>(offset_[i + 1] - offset_[i])};
}

std::vector<char> DofConstraints::master_flags() const {
  std::vector<char> flag(kind_.size(), 0);
  for (const auto& masters : masters_)
    for (const auto& [m, c] : masters) flag[static_cast<std::size_t>(m)] = 1;
  return flag;
}

Eigen::VectorXd DofConstraints::expand(const Eigen::VectorXd& reduced) const {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(num_dofs());
  for (int i = 0; i < num_dofs(); ++i)
    for (const Term& t : expansion(i)) full(i) += t.coefficient * reduced(t.reduced);
  return full;
}

Eigen::VectorXd DofConstraints::reduce(const Eigen::VectorXd& full) const {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(num_reduced_);
  for (int i = 0; i < num_dofs(); ++i)
    for (const Term& t : expansion(i)) r(t.reduced) += t.coefficient * full(i);
  return r;
}

Eigen::VectorXd DofConstraints::prescribed_values(double load_factor) const {
  require_finalized();
  Eigen::VectorXd g(num_dofs());
  for (int i = 0; i < num_dofs(); ++i) g(i) = load_factor * amplitude_[static_cast<std::size_t>(i)];
  return g;
}

}  // namespace spifit::solver
