#include "forward/scenes/common/energy_log.hpp"

#include "forward/io/series_archive.hpp"

namespace spifit::scene {
namespace {

std::vector<double> energy_row(double travel, const model::ModelEnergies& en, bool dynamic) {
  std::vector<double> row{travel, en.external_work, en.elastic, en.plastic, en.transverse_shear, en.contact_stored, en.friction_dissipation,
                          en.contact_offset_release};
  if (dynamic) {
    row.push_back(en.kinetic);
    row.push_back(en.damping);
  }
  row.push_back(en.balance_error());
  return row;
}

std::vector<io::Column> energy_columns(bool dynamic) {
  std::vector<io::Column> c{{"travel", "mm"}, {"external_work", "N mm"}, {"elastic", "N mm"}, {"plastic", "N mm"}, {"transverse_shear", "N mm"},
                            {"contact_stored", "N mm"}, {"friction_dissipation", "N mm"}, {"contact_offset_release", "N mm"}};
  if (dynamic) {
    c.push_back({"kinetic", "N mm"});
    c.push_back({"damping", "N mm"});
  }
  c.push_back({"balance_error", "N mm"});
  return c;
}

model::ModelEnergies energies_of_row(const std::vector<double>& row, bool dynamic) {
  model::ModelEnergies en;
  en.external_work = row[1];
  en.elastic = row[2];
  en.plastic = row[3];
  en.transverse_shear = row[4];
  en.contact_stored = row[5];
  en.friction_dissipation = row[6];
  en.contact_offset_release = row[7];
  if (dynamic) {
    en.kinetic = row[8];
    en.damping = row[9];
  }
  return en;
}

}  // namespace

EnergyLog::EnergyLog(std::string comment, const RunFiles& files, bool dynamic)
    : comment_(std::move(comment)), files_(files), table_(energy_columns(dynamic)), dynamic_(dynamic) {}

void EnergyLog::after_increment(const IncrementView& v) {
  last_ = model::energy_account(v.model);
  if (v.dynamics) {
    last_.kinetic = v.dynamics->kinetic;
    last_.damping = v.dynamics->damping_work;
    last_.external_work += v.dynamics->contact_work;
  }
  table_.add_row(energy_row(v.travel, last_, dynamic_));
}

void EnergyLog::write(WriteReason reason) {
  if (reason == WriteReason::increment) return;
  files_.write("energies.csv", comment_ + "\n" + table_.csv());
}

void EnergyLog::save(io::BinaryWriter& w) const { io::save_series_rows(w, table_); }

void EnergyLog::restore(io::BinaryReader& r) {
  io::load_series_rows(r, &table_, "energy");
  last_ = table_.empty() ? model::ModelEnergies{} : energies_of_row(table_.rows().back(), dynamic_);
}

}  // namespace spifit::scene
