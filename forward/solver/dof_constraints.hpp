#pragma once
// Linear constraints of the implicit solver (docs/design/numerics-shell.md, "Global solution"): the full
// DOF vector is u = T u_bar + g, where u_bar are the free (reduced) unknowns, g the prescribed
// values and T maps every DOF to a combination of reduced ones:
//   * free DOF: its own reduced unknown;
//   * prescribed DOF (supports, symmetry planes, imposed displacements): no reduced unknown,
//     value = amplitude x load factor;
//   * tied (slave) DOF: u_s = sum c_k u_mk, e.g. the cyclic condition of a pie, where the
//     DOFs of one edge are the rotated DOFs of the other.
// The reduced tangent T^T K T keeps the symmetry of K.
#include <Eigen/Core>

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace spifit::solver {

class DofConstraints {
 public:
  struct Term {
    int reduced = -1;
    double coefficient = 0.0;
  };

  explicit DofConstraints(int num_dofs);

  // u_dof = amplitude x load factor (amplitude 0: a support). Prescribing a DOF twice with
  // different amplitudes is an inconsistent constraint.
  void prescribe(int dof, double amplitude = 0.0);
  // u_slave = sum coefficient_k u_master_k.
  void tie(int slave, std::vector<std::pair<int, double>> masters);

  // Numbers the reduced unknowns. A tied master is replaced by its own expansion (chains of
  // ties). Throws std::invalid_argument("inconsistent constraint: ...") for a DOF both
  // prescribed and tied, a DOF tied to itself (directly or through a chain) or an index out of
  // range. Prescribed masters contribute to the slave's prescribed part.
  void finalize();

  bool finalized() const { return finalized_; }
  int num_dofs() const { return static_cast<int>(kind_.size()); }
  int num_reduced() const { return num_reduced_; }
  bool prescribed(int dof) const { return kind_[static_cast<std::size_t>(dof)] == Kind::prescribed; }
  bool tied(int dof) const { return kind_[static_cast<std::size_t>(dof)] == Kind::tied; }
  // Prescribed value per unit load factor (tied DOFs: the part from prescribed masters).
  double amplitude(int dof) const { return amplitude_[static_cast<std::size_t>(dof)]; }
  std::span<const Term> expansion(int dof) const;
  // Per DOF: 1 when some tied DOF refers to it (before or after finalize).
  std::vector<char> master_flags() const;

  Eigen::VectorXd expand(const Eigen::VectorXd& reduced) const;  // T u_bar
  Eigen::VectorXd reduce(const Eigen::VectorXd& full) const;     // T^T f
  Eigen::VectorXd prescribed_values(double load_factor) const;   // g

 private:
  enum class Kind { free, prescribed, tied };
  std::vector<Kind> kind_;
  std::vector<double> amplitude_;
  std::vector<std::vector<std::pair<int, double>>> masters_;
  std::vector<long> offset_;  // CSR of the expansion
  std::vector<Term> terms_;
  int num_reduced_ = 0;
  bool finalized_ = false;
  void check_dof(int dof, const char* what) const;
  void require_finalized() const;
  void expand_tied(std::size_t i, const std::vector<int>& reduced, std::vector<int>& state, std::vector<std::vector<Term>>& expanded);
};

}  // namespace spifit::solver
