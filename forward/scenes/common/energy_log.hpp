#pragma once
// The energy account of the model after every increment (model/model_energies.hpp) as a series
// and its file DIR/energies.csv: travel, the external work, the elastic, plastic and transverse
// shear energies, the contact's stored energy, frictional dissipation and offset release, and
// the balance error. The final account is the last row.
#include "forward/io/series.hpp"
#include "forward/model/model_energies.hpp"
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/run_observer.hpp"

#include <string>

namespace spifit::scene {

class EnergyLog : public RunObserver {
 public:
  // comment: the first line of energies.csv, "# ..." without the newline. dynamic: an explicit
  // run's log, with the kinetic energy and the damping's work as two more columns before the
  // balance error.
  EnergyLog(std::string comment, const RunFiles& files, bool dynamic = false);
  const io::Series& table() const { return table_; }
  // The account after the last increment (all zero before the first).
  const model::ModelEnergies& last() const { return last_; }

  std::string name() const override { return "energy_log"; }
  void after_increment(const IncrementView& v) override;
  void write(WriteReason reason) override;
  void save(io::BinaryWriter& w) const override;
  void restore(io::BinaryReader& r) override;

 private:
  std::string comment_;
  const RunFiles& files_;
  io::Series table_;
  model::ModelEnergies last_;
  bool dynamic_ = false;
};

}  // namespace spifit::scene
