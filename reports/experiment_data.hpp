#pragma once
// The data file of each experiment of a fit, DIR/experiments/NAME.csv (docs/reference/file-formats.md):
// columns X (or "index"), measured, simulated_initial, simulated_final.
#include "inverse/fit/fit_record.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace spifit::reports {

struct ExperimentData {
  bool ok = false;  // read, and (scalar experiments) exactly one row
  std::string x_column;
  std::vector<double> x, measured, initial, fitted;  // NaN where a cell is not a number
};

// A scalar experiment (one measured value): a material point's ("scalar") or an FE scene's
// observable ("fe_scalar"); every other kind is a curve.
inline bool is_scalar(const inverse::FitRecord::Experiment& e) { return e.kind == "scalar" || e.kind == "fe_scalar"; }

// `relative` as a path inside a directory (relative, no ".." at the front), else empty.
std::filesystem::path path_inside(const std::string& relative);

// Reads one data file; false and why (one line naming the file) when it cannot.
bool read_experiment_data(const std::filesystem::path& csv, ExperimentData* data, std::string* why);

// The data of every experiment of the record, in its order, read from DIR/DATA_FILE (or
// DIR/experiments/NAME.csv). An experiment whose file is missing, unsafe or malformed gets
// ok = false and a warning.
std::vector<ExperimentData> read_fit_data(const std::filesystem::path& dir, const inverse::FitRecord& record,
                                          std::vector<std::string>* warnings);

}  // namespace spifit::reports
