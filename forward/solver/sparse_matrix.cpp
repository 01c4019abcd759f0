#include "forward/solver/sparse_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spifit::solver {

long SparsePattern::find(int row, int col) const {
  const auto b = cols.begin() + row_ptr[row], e = cols.begin() + row_ptr[row + 1];
  const auto it = std::lower_bound(b, e, static_cast<long>(col));
  return (it != e && *it == col) ? static_cast<long>(it - cols.begin()) : -1;
}

SparsePattern build_pattern(int num_dofs, const std::vector<std::vector<int>>& element_dofs) {
  std::vector<std::vector<long>> rows(num_dofs);
  for (const auto& dofs : element_dofs) {
    for (int i : dofs) {
      if (i < 0 || i >= num_dofs) throw std::out_of_range("element dof out of range");
      for (int j : dofs) rows[i].push_back(j);
    }
  }
  SparsePattern p;
  p.rows = num_dofs;
  p.row_ptr.assign(num_dofs + 1, 0);
  for (int r = 0; r < num_dofs; ++r) {
    auto& v = rows[r];
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    if (v.empty()) v.push_back(r);  // keep the diagonal of an unconnected dof
    p.row_ptr[r + 1] = p.row_ptr[r] + static_cast<long>(v.size());
  }
  p.cols.reserve(p.row_ptr.back());
  for (const auto& v : rows) p.cols.insert(p.cols.end(), v.begin(), v.end());
  p.mirror.resize(p.cols.size());
  for (int r = 0; r < num_dofs; ++r)
    for (long k = p.row_ptr[r]; k < p.row_ptr[r + 1]; ++k) p.mirror[static_cast<std::size_t>(k)] = p.find(static_cast<int>(p.cols[k]), r);
  p.diagonal.resize(static_cast<std::size_t>(num_dofs));
  for (int r = 0; r < num_dofs; ++r) p.diagonal[static_cast<std::size_t>(r)] = p.find(r, r);  // present: each dof couples to itself
  return p;
}

AssemblyMap build_assembly_map(const SparsePattern& p, const std::vector<std::vector<int>>& element_dofs) {
  AssemblyMap m;
  m.positions.resize(element_dofs.size());
  for (std::size_t e = 0; e < element_dofs.size(); ++e) {
    const auto& d = element_dofs[e];
    auto& pos = m.positions[e];
    pos.resize(d.size() * d.size());
    for (std::size_t i = 0; i < d.size(); ++i) {
      for (std::size_t j = 0; j < d.size(); ++j) pos[i * d.size() + j] = p.find(d[i], d[j]);
    }
  }
  return m;
}

void SparseMatrix::add_element(const std::vector<long>& pos, const Eigen::MatrixXd& ke) {
  const long k = ke.rows();
  for (long i = 0; i < k; ++i) {
    for (long j = 0; j < k; ++j) values_[pos[i * k + j]] += ke(i, j);
  }
}

void SparseMatrix::add(int row, int col, double v) {
  const long p = pattern_->find(row, col);
  if (p < 0) throw std::out_of_range("entry not in the sparse pattern");
  values_[p] += v;
}

Eigen::VectorXd SparseMatrix::multiply(const Eigen::VectorXd& x) const {
  const auto& p = *pattern_;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(p.rows);
  for (int r = 0; r < p.rows; ++r) {
    double s = 0.0;
    for (long k = p.row_ptr[r]; k < p.row_ptr[r + 1]; ++k) s += values_[k] * x(p.cols[k]);
    y(r) = s;
  }
  return y;
}

Eigen::VectorXd SparseMatrix::diagonal() const {
  const auto& p = *pattern_;
  Eigen::VectorXd d(p.rows);
  for (int r = 0; r < p.rows; ++r) d(r) = values_[static_cast<std::size_t>(p.diagonal[static_cast<std::size_t>(r)])];
  return d;
}

void SparseMatrix::add_to_diagonal(const Eigen::VectorXd& d) {
  const auto& p = *pattern_;
  if (d.size() != p.rows) throw std::invalid_argument("add_to_diagonal: one value per row expected");
  for (int r = 0; r < p.rows; ++r) values_[static_cast<std::size_t>(p.diagonal[static_cast<std::size_t>(r)])] += d(r);
}

bool SparseMatrix::is_symmetric(double tol) const {
  const auto& p = *pattern_;
  double scale = 0.0;
  for (double v : values_) scale = std::max(scale, std::abs(v));
  const bool has_mirror = p.mirror.size() == p.cols.size();  // patterns not made by build_pattern search
  for (int r = 0; r < p.rows; ++r) {
    for (long k = p.row_ptr[r]; k < p.row_ptr[r + 1]; ++k) {
      const long t = has_mirror ? p.mirror[static_cast<std::size_t>(k)] : p.find(static_cast<int>(p.cols[k]), r);
      if (t >= 0 && t < k) continue;  // the pair was compared from its other entry
      const double other = t >= 0 ? values_[t] : 0.0;
      if (std::abs(values_[k] - other) > tol * scale) return false;
    }
  }
  return true;
}

void SparseMatrix::assign_symmetric_part(const SparseMatrix& a) {
  const auto& p = *pattern_;
  if (a.pattern_ != pattern_) throw std::invalid_argument("assign_symmetric_part: the matrices have different patterns");
  if (p.mirror.size() != p.cols.size()) throw std::invalid_argument("assign_symmetric_part: the pattern has no mirror map");
  for (std::size_t k = 0; k < values_.size(); ++k) {
    const long t = p.mirror[k];
    if (t < 0) throw std::invalid_argument("assign_symmetric_part: the pattern is not symmetric");
    values_[k] = 0.5 * (a.values_[k] + a.values_[static_cast<std::size_t>(t)]);
  }
}

}  // namespace spifit::solver
