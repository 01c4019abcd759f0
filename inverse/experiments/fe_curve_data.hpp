#pragma once
// The measured curve of an FE experiment, read from its data file (every FE experiment kind
// that compares a curve uses it: forces against travel, cone sections).
#include "forward/io/toml_reader.hpp"
#include "inverse/experiments/measurement.hpp"

#include <string>
#include <vector>

namespace spifit::inverse {

// The measured (x, y) of an FE curve from the experiment's `data` file, read from fit file
// `path`: x strictly increasing inside [lo, hi] (else an InputError naming the data file, the
// column and the value, with range_note after the range), per-point weights from weight_column,
// the unit of y, and the table itself for further columns.
struct CurveData {
  std::vector<double> xs, ys, weights;
  std::string y_unit, data_path;
  MeasurementTable table;
};
// The columns come in the units the simulation compares them in (x_unit, y_unit; "" for
// counts and ratios), converted from the header's units (convert_column, measurement.hpp).
CurveData read_curve_data(const io::TomlTable& e, const std::string& path, const std::string& x, const std::string& y, double lo, double hi,
                          const std::string& range_note, const std::string& x_unit, const std::string& y_unit);

}  // namespace spifit::inverse
