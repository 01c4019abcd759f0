#pragma once
// Minimal CSV table builder: one header row, numbers written with 17 significant digits
// so that a curve read back is bit-identical (golden outputs, determinism).
#include <string>
#include <vector>

namespace spifit::io {

// Appends one CSV row of numbers (%.17g, comma-separated, newline) to *out.
void append_csv_row(const std::vector<double>& values, std::string* out);

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> columns);
  void add_row(const std::vector<double>& values);  // throws std::logic_error on a width mismatch
  std::string str() const;
  std::size_t rows() const { return rows_; }

 private:
  std::vector<std::string> columns_;
  std::string body_;
  std::size_t rows_ = 0;
};

}  // namespace spifit::io
