#include "forward/scenes/common/sensitivity_log.hpp"

#include "forward/io/series_archive.hpp"
#include "forward/model/fe_model.hpp"

namespace spifit::scene {
std::vector<io::Column> sensitivity_log_columns(const std::vector<std::string>& names, const std::vector<std::string>& units) {
  std::vector<io::Column> c{{"time", "s"}, {"lambda", ""}};
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& u = units[k];
    const std::string per = u.empty() ? "N" : u.find('/') != std::string::npos ? "N/(" + u + ")" : "N/" + u;
    for (const char* f : {"Fx", "Fy", "Fz"}) c.push_back({"d" + std::string(f) + "/d(" + names[k] + ")", per});
    for (const char* f : {"Fx", "Fy", "Fz"}) c.push_back({names[k] + "*d" + std::string(f) + "/d(" + names[k] + ")", "N"});
  }
  return c;
}

std::size_t sensitivity_log_parameters(const io::Series& table) {
  const std::size_t columns = table.columns().size();
  return columns >= 8 && (columns - 2) % 6 == 0 ? (columns - 2) / 6 : 0;
}

SensitivityLog::SensitivityLog(std::vector<std::string> names, const std::vector<std::string>& units, std::vector<double> values,
                               std::string comment, std::function<Eigen::Vector3d(const Eigen::Vector3d&)> whole, const RunFiles& files)
    : names_(std::move(names)), values_(std::move(values)), comment_(std::move(comment)), whole_(std::move(whole)), files_(files),
      table_(sensitivity_log_columns(names_, units)) {}

void SensitivityLog::after_increment(const IncrementView& v) {
  const auto& d = v.model.contribution_force_sensitivity();
  std::vector<double> row{v.time, v.lambda};
  for (std::size_t k = 0; k < names_.size(); ++k) {
    const Eigen::Vector3d raw = d.col(static_cast<Eigen::Index>(k));
    const Eigen::Vector3d f = whole_ ? whole_(raw) : raw;
    row.insert(row.end(), {f.x(), f.y(), f.z()});
    row.insert(row.end(), {values_[k] * f.x(), values_[k] * f.y(), values_[k] * f.z()});
  }
  table_.add_row(std::move(row));
}

void SensitivityLog::write(WriteReason reason) {
  if (reason == WriteReason::increment) return;
  files_.write("sensitivities.csv", comment_ + "\n" + table_.csv());
}

void SensitivityLog::save(io::BinaryWriter& w) const { io::save_series_rows(w, table_); }

void SensitivityLog::restore(io::BinaryReader& r) { io::load_series_rows(r, &table_, "sensitivity"); }

}  // namespace spifit::scene
