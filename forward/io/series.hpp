#pragma once
// A series of a run: rows of numbers under named columns with units, kept in memory (the
// typed results of the scenes hold them) and rendered as CSV with a header row "name [unit]"
// and 17 significant digits, so that a series read back from its file is bit-identical. The
// CSV text grows with the rows (a file rewritten during a long run costs its size, not a
// re-formatting of every number).
#include <string>
#include <vector>

namespace spifit::io {

struct Column {
  std::string name;
  std::string unit;  // empty: a count or a ratio (header "name")
};

// "name [unit]" -> {name, unit}; a header without brackets has no unit.
Column parse_column(const std::string& header);
std::vector<Column> parse_columns(const std::vector<std::string>& headers);

class Series {
 public:
  Series() = default;
  explicit Series(std::vector<Column> columns);

  const std::vector<Column>& columns() const { return columns_; }
  std::size_t size() const { return rows_.size(); }
  bool empty() const { return rows_.empty(); }
  // Throws std::logic_error when the row's width differs from the columns'.
  void add_row(std::vector<double> row);
  void clear();
  const std::vector<std::vector<double>>& rows() const { return rows_; }
  const std::vector<double>& row(std::size_t i) const { return rows_[i]; }
  // Index of a column by name, -1 when there is none.
  int find(const std::string& name) const;
  // The values of a column; std::out_of_range naming the column when there is none.
  std::vector<double> column(const std::string& name) const;
  // Header row and rows (no comment line).
  std::string csv() const;

 private:
  std::vector<Column> columns_;
  std::vector<std::vector<double>> rows_;
  std::string body_;  // the rows as CSV
};

}  // namespace spifit::io
