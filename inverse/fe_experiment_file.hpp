#pragma once
// An [[experiment]] of a fit file on an FE scene (indent, indent_line, line, cone, ...): a force
// curve (data, x, y) or a scalar observable of the scene kind (observable, value, window or
// contours). Schema in docs/reference/file-formats.md; errors name the file, key and value.
#include "forward/io/toml_reader.hpp"
#include "inverse/fe_experiment.hpp"
#include "inverse/measurement.hpp"

#include <memory>
#include <string>

namespace spifit::inverse {

// e: the [[experiment]] table of fit file `path`; scene: read from its file (its card is
// replaced by the fit's); noise and weight already read and checked.
std::unique_ptr<Experiment> read_fe_experiment(const io::TomlTable& e, const std::string& path, FeExperimentBase base);

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

// The keys an FE [[experiment]] may hold.
const std::vector<std::string>& fe_experiment_keys();

}  // namespace spifit::inverse
