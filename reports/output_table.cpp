#include "reports/output_table.hpp"

#include <cstdlib>
#include <fstream>
#include <limits>

namespace spifit::reports {

int OutputTable::find(const std::string& name) const {
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return static_cast<int>(k);
  return -1;
}

std::vector<double> OutputTable::column(const std::string& name) const {
  const int k = find(name);
  return k < 0 ? std::vector<double>{} : columns[static_cast<std::size_t>(k)];
}

std::string OutputTable::unit(const std::string& name) const {
  const int k = find(name);
  return k < 0 ? std::string() : units[static_cast<std::size_t>(k)];
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',') out.emplace_back();
    else if (c != '\r') out.back() += c;
  }
  return out;
}

double csv_number(const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return (end == s.c_str() || *end != '\0') ? std::numeric_limits<double>::quiet_NaN() : v;
}

bool read_output_table(const std::filesystem::path& csv, OutputTable* t, std::string* why) {
  std::ifstream f(csv);
  if (!f) {
    *why = "cannot read " + csv.string();
    return false;
  }
  std::string line;
  bool header = false;
  while (std::getline(f, line)) {
    if (line.empty() || line[0] == '#') continue;
    header = true;
    break;
  }
  if (!header) {
    *why = csv.string() + " has no header";
    return false;
  }
  *t = OutputTable{};
  for (const std::string& cell : split_csv_line(line)) {
    const auto open = cell.find(" [");
    const bool has_unit = open != std::string::npos && cell.back() == ']';
    t->names.push_back(has_unit ? cell.substr(0, open) : cell);
    t->units.push_back(has_unit ? cell.substr(open + 2, cell.size() - open - 3) : "");
  }
  t->columns.assign(t->names.size(), {});
  while (std::getline(f, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto cells = split_csv_line(line);
    if (cells.size() != t->names.size()) break;  // a row cut off by a killed run
    for (std::size_t k = 0; k < cells.size(); ++k) t->columns[k].push_back(csv_number(cells[k]));
  }
  return true;
}

}  // namespace spifit::reports
