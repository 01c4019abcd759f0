#pragma once
// Data rows of a CSV file written by spifit (comment lines '#' and the header skipped), as numbers.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace spifit::test {

inline std::vector<std::vector<double>> read_csv_rows(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::vector<std::vector<double>> rows;
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace spifit::test
