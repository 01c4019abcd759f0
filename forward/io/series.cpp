#include "forward/io/series.hpp"

#include "forward/io/csv_writer.hpp"

#include <stdexcept>

namespace spifit::io {

Column parse_column(const std::string& header) {
  const auto open = header.find(" [");
  if (open == std::string::npos || header.back() != ']') return {header, ""};
  return {header.substr(0, open), header.substr(open + 2, header.size() - open - 3)};
}

std::vector<Column> parse_columns(const std::vector<std::string>& headers) {
  std::vector<Column> out;
  for (const auto& h : headers) out.push_back(parse_column(h));
  return out;
}

Series::Series(std::vector<Column> columns) : columns_(std::move(columns)) {}

void Series::add_row(std::vector<double> row) {
  if (row.size() != columns_.size())
    throw std::logic_error("series row of " + std::to_string(row.size()) + " values for " + std::to_string(columns_.size()) + " columns");
  append_csv_row(row, &body_);
  rows_.push_back(std::move(row));
}

void Series::clear() {
  rows_.clear();
  body_.clear();
}

int Series::find(const std::string& name) const {
  for (std::size_t i = 0; i < columns_.size(); ++i)
    if (columns_[i].name == name) return static_cast<int>(i);
  return -1;
}

std::vector<double> Series::column(const std::string& name) const {
  const int k = find(name);
  if (k < 0) throw std::out_of_range("no column \"" + name + "\" in the series");
  std::vector<double> v;
  v.reserve(rows_.size());
  for (const auto& r : rows_) v.push_back(r[static_cast<std::size_t>(k)]);
  return v;
}

std::string Series::csv() const {
  std::string out;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i) out += ',';
    out += columns_[i].name;
    if (!columns_[i].unit.empty()) out += " [" + columns_[i].unit + "]";
  }
  out += '\n';
  return out + body_;
}

}  // namespace spifit::io
