#include "forward/scenes/common/vtu_log.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/model/model_vtu.hpp"
#include "forward/model/fe_model.hpp"

#include <filesystem>

namespace spifit::scene {

VtuLog::VtuLog(const RunFiles& files, int every, const std::string& stem) : files_(files), stem_(stem), every_(every) {}

void VtuLog::open() {
  if (pvd_ || !files_.enabled()) return;
  const std::filesystem::path dir = files_.directory()->path() / "vtu";
  std::filesystem::create_directories(dir);
  files_.directory()->record();  // vtu/ in the manifest
  pvd_ = std::make_unique<mesh::PvdCollection>(dir, stem_);
}

void VtuLog::at_start(const model::FeModel& model) {
  open();
  if (pvd_) pvd_->write_step(0.0, model.mesh(), frame(model));
}

void VtuLog::after_increment(const IncrementView& v) {
  ++increments_;
  if (pvd_ && every_ > 0 && increments_ % every_ == 0) pvd_->write_step(v.time, v.model.mesh(), frame(v.model));
}

void VtuLog::at_end(const model::FeModel& model, double time) {
  if (pvd_ && increments_ > 0 && (every_ == 0 || increments_ % every_ != 0)) pvd_->write_step(time, model.mesh(), frame(model));
}

void VtuLog::save(io::BinaryWriter& w) const {
  w.i64(increments_);
  const auto& entries = pvd_ ? pvd_->entries() : std::vector<std::pair<double, std::string>>{};
  w.i64(static_cast<std::int64_t>(entries.size()));
  for (const auto& [t, f] : entries) {
    w.f64(t);
    w.string(f);
  }
}

void VtuLog::restore(io::BinaryReader& r) {
  increments_ = static_cast<int>(r.i64());
  const std::int64_t n = r.i64();
  if (n < 0 || n > 100'000'000) throw io::ArchiveError("invalid VTU step count " + std::to_string(n));
  std::vector<std::pair<double, std::string>> entries;
  for (std::int64_t i = 0; i < n; ++i) {
    const double t = r.f64();
    entries.emplace_back(t, r.string());
  }
  open();
  if (pvd_) pvd_->restore(std::move(entries));
}

}  // namespace spifit::scene
