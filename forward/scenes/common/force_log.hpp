#pragma once
// The tool force after every increment: the typed history (tool_force_history.hpp) and its file
// DIR/force.csv, whose columns and first comment line the scene kind chooses (a kind's polar
// components, contour and move annotations are functions of a sample). The force recorded is
// the real tool's (ToolContact::force) mapped by `whole`, e.g. a half model's force mirrored to
// the whole sheet.
#include "forward/io/series.hpp"
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/run_observer.hpp"
#include "forward/scenes/common/tool_force_history.hpp"

#include <functional>
#include <string>
#include <vector>

namespace spifit::scene {

struct ForceLogFormat {
  std::vector<io::Column> columns;
  std::string comment;  // the first line of force.csv, "# ..." without the newline
  std::function<std::vector<double>(const ToolForceSample&)> row;
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> whole;  // empty: the force as it is
};

class ForceLog : public RunObserver {
 public:
  ForceLog(ForceLogFormat format, const RunFiles& files);
  const ToolForceHistory& history() const { return history_; }
  const io::Series& table() const { return table_; }

  std::string name() const override { return "force_log"; }
  void after_increment(const IncrementView& v) override;
  void write(WriteReason reason) override;
  void save(io::BinaryWriter& w) const override;
  void restore(io::BinaryReader& r) override;

 private:
  ForceLogFormat format_;
  const RunFiles& files_;
  ToolForceHistory history_;
  io::Series table_;
};

}  // namespace spifit::scene
