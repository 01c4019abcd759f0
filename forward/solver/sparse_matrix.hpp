#pragma once
// Sparse matrices of the implicit FE solver (docs/design/numerics-shell.md, "Global solution"): a CSR
// pattern built once from the element connectivity, an assembly map giving, for every element, the
// positions of its entries in the value array, and deterministic assembly (element matrices may be
// computed in parallel; they are added in element order).
#include <Eigen/Core>

#include <vector>

namespace spifit::solver {

struct SparsePattern {
  int rows = 0;
  std::vector<long> row_ptr;  // size rows + 1
  std::vector<long> cols;     // column indices, sorted within each row
  std::vector<long> mirror;   // mirror[k] = position of (cols[k], row of k), -1 if absent; set by build_pattern
  std::vector<long> diagonal; // diagonal[r] = position of (r, r) (every row has one); set by build_pattern
  long nonzeros() const { return static_cast<long>(cols.size()); }
  long find(int row, int col) const;  // -1 when (row, col) is not in the pattern
};

// Union of the dense blocks of every element: element e couples all of element_dofs[e].
SparsePattern build_pattern(int num_dofs, const std::vector<std::vector<int>>& element_dofs);

// positions[e][i * k + j] = index in the value array of (element_dofs[e][i], element_dofs[e][j]).
struct AssemblyMap {
  std::vector<std::vector<long>> positions;
};
AssemblyMap build_assembly_map(const SparsePattern& pattern, const std::vector<std::vector<int>>& element_dofs);

class SparseMatrix {
 public:
  explicit SparseMatrix(const SparsePattern& pattern) : pattern_(&pattern), values_(pattern.cols.size(), 0.0) {}
  const SparsePattern& pattern() const { return *pattern_; }
  std::vector<double>& values() { return values_; }
  const std::vector<double>& values() const { return values_; }
  void set_zero() { std::fill(values_.begin(), values_.end(), 0.0); }
  void add_element(const std::vector<long>& positions, const Eigen::MatrixXd& ke);
  void add(int row, int col, double v);  // must be in the pattern
  Eigen::VectorXd multiply(const Eigen::VectorXd& x) const;
  Eigen::VectorXd diagonal() const;
  void add_to_diagonal(const Eigen::VectorXd& d);  // d: one value per row
  bool is_symmetric(double relative_tolerance) const;
  // This matrix becomes (a + a^T) / 2; a has this matrix's pattern, which must be symmetric.
  void assign_symmetric_part(const SparseMatrix& a);

 private:
  const SparsePattern* pattern_;
  std::vector<double> values_;
};

}  // namespace spifit::solver
