#pragma once
// A CSV table that spifit wrote into an output directory (force.csv, energies.csv,
// contours.csv, sections/*.csv): leading '#' comment lines, a header of "name [unit]" cells and
// numeric rows. A partial file (a run still going or killed) is read up to its last complete row.
#include <filesystem>
#include <string>
#include <vector>

namespace spifit::reports {

struct OutputTable {
  std::vector<std::string> names, units;  // per column: "Fz", "N"
  std::vector<std::vector<double>> columns;
  bool has(const std::string& name) const { return find(name) >= 0; }
  int find(const std::string& name) const;
  // The column's values (empty when there is no such column).
  std::vector<double> column(const std::string& name) const;
  std::string unit(const std::string& name) const;
  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
};

// The cells of one CSV line (no quoting: spifit writes none), and a cell as a number (NaN when
// it is not one).
std::vector<std::string> split_csv_line(const std::string& line);
double csv_number(const std::string& cell);

// false with *why when the file is missing or has no header.
bool read_output_table(const std::filesystem::path& csv, OutputTable* table, std::string* why);

}  // namespace spifit::reports
