#include "forward/scenes/common/sensitivity_log.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/model/fe_model.hpp"

namespace spifit::scene {
namespace {

std::vector<io::Column> columns(const std::vector<std::string>& names, const std::vector<std::string>& units) {
  std::vector<io::Column> c{{"time", "s"}, {"lambda", ""}};
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& u = units[k];
    const std::string per = u.empty() ? "N" : u.find('/') != std::string::npos ? "N/(" + u + ")" : "N/" + u;
    for (const char* f : {"Fx", "Fy", "Fz"}) c.push_back({"d" + std::string(f) + "/d(" + names[k] + ")", per});
    for (const char* f : {"Fx", "Fy", "Fz"}) c.push_back({names[k] + "*d" + std::string(f) + "/d(" + names[k] + ")", "N"});
  }
  return c;
}

}  // namespace

SensitivityLog::SensitivityLog(std::vector<std::string> names, const std::vector<std::string>& units, std::vector<double> values,
                               std::string comment, std::function<Eigen::Vector3d(const Eigen::Vector3d&)> whole, const RunFiles& files)
    : names_(std::move(names)), values_(std::move(values)), comment_(std::move(comment)), whole_(std::move(whole)), files_(files),
      table_(columns(names_, units)) {}

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

void SensitivityLog::save(io::BinaryWriter& w) const {
  w.i64(static_cast<std::int64_t>(table_.size()));
  for (const auto& row : table_.rows()) w.f64s(row);
}

void SensitivityLog::restore(io::BinaryReader& r) {
  table_.clear();
  const std::int64_t n = r.i64();
  if (n < 0 || n > 100'000'000) throw io::ArchiveError("invalid sensitivity row count " + std::to_string(n));
  for (std::int64_t i = 0; i < n; ++i) {
    std::vector<double> row = r.f64s();
    if (row.size() != table_.columns().size()) throw io::ArchiveError("sensitivity row of another width (other parameters)");
    table_.add_row(std::move(row));
  }
}

}  // namespace spifit::scene
