#include "forward/io/csv_writer.hpp"

#include <cstdio>
#include <stdexcept>

namespace spifit::io {

CsvTable::CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}

void append_csv_row(const std::vector<double>& values, std::string* out) {
  char buf[40];
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.17g", values[i]);
    if (i) *out += ',';
    *out += buf;
  }
  *out += '\n';
}

void CsvTable::add_row(const std::vector<double>& values) {
  if (values.size() != columns_.size()) throw std::logic_error("CSV row width does not match the header");
  append_csv_row(values, &body_);
  ++rows_;
}

std::string CsvTable::str() const {
  std::string out;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i) out += ',';
    out += columns_[i];
  }
  out += '\n';
  return out + body_;
}

}  // namespace spifit::io
