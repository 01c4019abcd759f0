#include "inverse/experiments/fe_curve_data.hpp"

#include "forward/io/input_error.hpp"

#include <filesystem>

namespace spifit::inverse {

using io::format_number;
using io::InputError;

CurveData read_curve_data(const io::TomlTable& e, const std::string& path, const std::string& x, const std::string& y, double lo, double hi,
                          const std::string& range_note, const std::string& x_unit, const std::string& y_unit) {
  const std::string data_path = resolve_path(path, e.string("data"));
  MeasurementTable table = read_measurement_csv(data_path);
  table.column(x);  // a missing column named first
  table.column(y);
  convert_column(table, x, x_unit);
  convert_column(table, y, y_unit);
  CurveData d{table.column(x), table.column(y), {}, table.units.at(y), data_path, {}};
  if (e.has("weight_column")) {
    d.weights = table.column(e.string("weight_column"));
    for (double w : d.weights)
      if (!(w >= 0)) throw InputError(data_path, "column " + e.string("weight_column"), format_number(w), "point weights must be >= 0");
  }
  if (d.xs.empty()) throw InputError(data_path, "column " + x, "", "no data rows");
  for (std::size_t i = 0; i < d.xs.size(); ++i) {
    if (i > 0 && !(d.xs[i] > d.xs[i - 1]))
      throw InputError(data_path, "column " + x, format_number(d.xs[i]), "abscissa must increase strictly (row " + std::to_string(i + 1) + ")");
    if (d.xs[i] < lo - 1e-9 || d.xs[i] > hi + 1e-9)
      throw InputError(data_path, "column " + x, format_number(d.xs[i]),
                       "outside the simulated range [" + format_number(lo) + ", " + format_number(hi) + "] " + range_note);
  }
  d.table = std::move(table);
  return d;
}

}  // namespace spifit::inverse
