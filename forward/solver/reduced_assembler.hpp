#pragma once
// Assembly of element contributions into the reduced system T^T K T u_bar = -T^T r
// (dof_constraints.hpp). The pattern over the reduced unknowns and every element's positions
// in it are built once; elements whose DOFs are all free or prescribed (the common case)
// are scattered directly, elements with tied DOFs go through their small expansion matrix.
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/sparse_matrix.hpp"

#include <Eigen/Core>

#include <vector>

namespace spifit::solver {

class ReducedAssembler {
 public:
  ReducedAssembler(const DofConstraints& constraints, const std::vector<std::vector<int>>& element_dofs);

  const SparsePattern& pattern() const { return pattern_; }
  int num_reduced() const { return constraints_->num_reduced(); }

  // Adds element e: its residual re (full local DOFs) plus ke * dg (the prescribed part of
  // the correction, local; may be empty) to r_bar, and ke to K_bar (if k_bar is non-null).
  void add(int e, const Eigen::VectorXd& re, const Eigen::MatrixXd* ke, const Eigen::VectorXd* dg_local,
           Eigen::VectorXd* r_bar, SparseMatrix* k_bar) const;
  // Adds the rows [row_begin, row_end) of element e's ke to K_bar. Threads that own disjoint
  // row ranges and each add the elements in the same order build the same K as add(), bit for
  // bit, in parallel.
  void add_tangent_rows(int e, const Eigen::MatrixXd& ke, int row_begin, int row_end, SparseMatrix* k_bar) const;

 private:
  const DofConstraints* constraints_;
  const std::vector<std::vector<int>>* element_dofs_;
  std::vector<std::vector<int>> reduced_dofs_;     // per element: unique reduced unknowns
  std::vector<Eigen::MatrixXd> expansion_;         // per element with tied DOFs: S (local x reduced)
  std::vector<std::vector<int>> direct_;           // per element without ties: local -> position in reduced_dofs_ or -1
  std::vector<char> has_ties_;
  SparsePattern pattern_;
  AssemblyMap map_;
};

}  // namespace spifit::solver
