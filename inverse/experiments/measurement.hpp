#pragma once
// A measurement file: CSV with '#' comment lines (provenance), one header row naming the
// columns as "name" or "name [unit]", then numbers. Errors name the file, line and value.
#include <map>
#include <string>
#include <vector>

namespace spifit::inverse {

struct MeasurementTable {
  std::string file;
  std::vector<std::string> comments;             // the '#' lines, without '#'
  std::vector<std::string> names;                // column names without units
  std::map<std::string, std::string> units;      // name -> unit ("" if none)
  std::map<std::string, std::vector<double>> columns;

  bool has(const std::string& name) const { return columns.count(name) > 0; }
  const std::vector<double>& column(const std::string& name) const;  // throws InputError
  std::size_t rows() const { return columns.empty() ? 0 : columns.begin()->second.size(); }
};

MeasurementTable read_measurement_csv(const std::string& path);

// Puts a column into `unit`, the unit the simulation compares it in: values scaled from the
// header's unit where the two convert (% to a fraction; kN to N; GPa, kPa, Pa, N/mm^2 to MPa;
// um, cm, m to mm; ms, min to s); a column without a unit is taken as already in `unit`.
// ("" and "-" both mean dimensionless.) InputError naming the file, column and unit otherwise.
void convert_column(MeasurementTable& t, const std::string& column, const std::string& unit);

// A path written in file `base_file` (a fit file's scene or data), relative to that file's folder.
std::string resolve_path(const std::string& base_file, const std::string& path);

}  // namespace spifit::inverse
