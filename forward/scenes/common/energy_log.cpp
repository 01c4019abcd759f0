#include "forward/scenes/common/energy_log.hpp"

#include "forward/io/binary_archive.hpp"

namespace spifit::scene {
namespace {

std::vector<double> energy_row(double travel, const model::ModelEnergies& en) {
  return {travel, en.external_work, en.elastic, en.plastic, en.transverse_shear, en.contact_stored, en.friction_dissipation,
          en.contact_offset_release, en.balance_error()};
}

model::ModelEnergies energies_of_row(const std::vector<double>& row) {
  model::ModelEnergies en;
  en.external_work = row[1];
  en.elastic = row[2];
  en.plastic = row[3];
  en.transverse_shear = row[4];
  en.contact_stored = row[5];
  en.friction_dissipation = row[6];
  en.contact_offset_release = row[7];
  return en;
}

}  // namespace

EnergyLog::EnergyLog(std::string comment, const RunFiles& files)
    : comment_(std::move(comment)), files_(files),
      table_({{"travel", "mm"}, {"external_work", "N mm"}, {"elastic", "N mm"}, {"plastic", "N mm"}, {"transverse_shear", "N mm"},
              {"contact_stored", "N mm"}, {"friction_dissipation", "N mm"}, {"contact_offset_release", "N mm"},
              {"balance_error", "N mm"}}) {}

void EnergyLog::after_increment(const IncrementView& v) {
  last_ = model::energy_account(v.model);
  table_.add_row(energy_row(v.travel, last_));
}

void EnergyLog::write(WriteReason reason) {
  if (reason == WriteReason::increment) return;
  files_.write("energies.csv", comment_ + "\n" + table_.csv());
}

void EnergyLog::save(io::BinaryWriter& w) const {
  w.i64(static_cast<std::int64_t>(table_.size()));
  for (const auto& row : table_.rows()) w.f64s(row);
}

void EnergyLog::restore(io::BinaryReader& r) {
  table_.clear();
  const std::int64_t n = r.i64();
  if (n < 0 || n > 1'000'000'000) throw io::ArchiveError("invalid energy row count " + std::to_string(n));
  for (std::int64_t i = 0; i < n; ++i) {
    std::vector<double> row = r.f64s();
    if (row.size() != table_.columns().size()) throw io::ArchiveError("energy row of another width");
    table_.add_row(row);
  }
  last_ = table_.empty() ? model::ModelEnergies{} : energies_of_row(table_.rows().back());
}

}  // namespace spifit::scene
