#include "reports/experiment_data.hpp"

#include "reports/output_table.hpp"

#include <cstdlib>
#include <fstream>
#include <limits>

namespace spifit::reports {

namespace fs = std::filesystem;

namespace {

double cell_value(const std::vector<std::string>& cells, int k) {
  if (k < 0) return std::numeric_limits<double>::quiet_NaN();
  return csv_number(cells[static_cast<std::size_t>(k)]);
}

}  // namespace

fs::path path_inside(const std::string& rel) {
  if (rel.empty()) return {};
  const fs::path p = fs::path(rel).lexically_normal();
  if (p.is_absolute() || p.empty() || *p.begin() == "..") return {};
  return p;
}

bool read_experiment_data(const fs::path& path, ExperimentData* e, std::string* why) {
  std::ifstream f(path);
  if (!f) {
    *why = "cannot read " + path.string();
    return false;
  }
  std::string line;
  if (!std::getline(f, line)) {
    *why = path.string() + " is empty";
    return false;
  }
  const auto header = split_csv_line(line);
  int im = -1, ii = -1, ifi = -1;
  for (std::size_t k = 0; k < header.size(); ++k) {
    if (header[k] == "measured") im = static_cast<int>(k);
    if (header[k] == "simulated_initial") ii = static_cast<int>(k);
    if (header[k] == "simulated_final") ifi = static_cast<int>(k);
  }
  if (im <= 0 || ifi <= 0) {
    *why = path.string() + ": expected the columns X, measured, simulated_initial, simulated_final";
    return false;
  }
  e->x_column = header[0];
  int row = 1;
  while (std::getline(f, line)) {
    ++row;
    if (line.empty() || line == "\r") continue;
    const auto cells = split_csv_line(line);
    if (cells.size() != header.size()) {
      *why = path.string() + ": row " + std::to_string(row) + " has " + std::to_string(cells.size()) + " cells, the header " +
             std::to_string(header.size());
      return false;
    }
    e->x.push_back(cell_value(cells, 0));
    e->measured.push_back(cell_value(cells, im));
    e->initial.push_back(cell_value(cells, ii));
    e->fitted.push_back(cell_value(cells, ifi));
  }
  if (e->measured.empty()) {
    *why = path.string() + " has no data rows";
    return false;
  }
  e->ok = true;
  return true;
}

std::vector<ExperimentData> read_fit_data(const fs::path& dir, const inverse::FitRecord& record, std::vector<std::string>* warnings) {
  std::vector<ExperimentData> out(record.experiments.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto& e = record.experiments[i];
    fs::path rel = path_inside(e.data_file);
    if (rel.empty()) rel = path_inside("experiments/" + e.name + ".csv");
    std::string why = "experiment " + e.name + ": no safe data file name";
    if (rel.empty() || !read_experiment_data(dir / rel, &out[i], &why)) {
      warnings->push_back(why + "; no table or plot for it");
      continue;
    }
    if (is_scalar(e) && out[i].measured.size() != 1) {
      out[i].ok = false;
      warnings->push_back((dir / rel).string() + ": a scalar experiment needs exactly one row");
    }
  }
  return out;
}

}  // namespace spifit::reports
