#pragma once
// The tool force's parameter sensitivities after every increment (a run with
// RunControl::sensitivities; docs/design/sensitivities.md): DIR/sensitivities.csv with, per
// parameter p, dF/dp of the force BY the sheet ON the tool (N per unit of p) and the scaled
// p dF/dp (N: the force change of a 100 % change of p, to first order), mapped to the whole
// sheet like force.csv (a half model's force mirrored).
#include "forward/io/series.hpp"
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/run_observer.hpp"

#include <functional>
#include <string>
#include <vector>

namespace spifit::scene {

// The table's columns: time, lambda, then per parameter dFx, dFy, dFz/d(name) [N per unit] and
// name*dFx, dFy, dFz/d(name) [N].
std::vector<io::Column> sensitivity_log_columns(const std::vector<std::string>& names, const std::vector<std::string>& units);
// The number of parameters a table of that layout holds; 0 when it is not of that layout.
std::size_t sensitivity_log_parameters(const io::Series& table);

class SensitivityLog : public RunObserver {
 public:
  // names, units, values: the parameters, their units and values; comment: the first line of the file
  // ("# ..."); whole: as ForceLogFormat::whole (linear), empty for the force as it is.
  SensitivityLog(std::vector<std::string> names, const std::vector<std::string>& units, std::vector<double> values, std::string comment,
                 std::function<Eigen::Vector3d(const Eigen::Vector3d&)> whole, const RunFiles& files);
  const io::Series& table() const { return table_; }

  std::string name() const override { return "sensitivity_log"; }
  void after_increment(const IncrementView& v) override;
  void write(WriteReason reason) override;
  void save(io::BinaryWriter& w) const override;
  void restore(io::BinaryReader& r) override;

 private:
  std::vector<std::string> names_;
  std::vector<double> values_;
  std::string comment_;
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> whole_;
  const RunFiles& files_;
  io::Series table_;
};

}  // namespace spifit::scene
