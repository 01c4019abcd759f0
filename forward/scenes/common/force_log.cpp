#include "forward/scenes/common/force_log.hpp"

#include "forward/model/fe_model.hpp"
#include "forward/model/tool_contact.hpp"

namespace spifit::scene {

ForceLog::ForceLog(ForceLogFormat format, const RunFiles& files) : format_(std::move(format)), files_(files), table_(format_.columns) {}

void ForceLog::after_increment(const IncrementView& v) {
  ToolForceSample s;
  s.travel = v.travel;
  s.time = v.time;
  s.centre = v.tool.tool().centre;
  // An explicit run's force: filtered over the output interval (the instantaneous one rings).
  const Eigen::Vector3d f = v.dynamics ? v.dynamics->filtered_tool_force : v.tool.force();
  s.force = format_.whole ? format_.whole(f) : f;
  s.penetration = v.tool.summary().max_penetration;
  s.surface_penetration = v.tool.surface_penetration(v.model);
  s.iterations = v.report.iterations;
  history_.add(s);
  table_.add_row(format_.row(s));
}

void ForceLog::write(WriteReason reason) {
  if (reason == WriteReason::increment) return;
  files_.write("force.csv", format_.comment + "\n" + table_.csv());
}

void ForceLog::save(io::BinaryWriter& w) const { history_.save(w); }

void ForceLog::restore(io::BinaryReader& r) {
  history_.load(r);
  table_.clear();
  for (const auto& s : history_.samples()) table_.add_row(format_.row(s));
}

}  // namespace spifit::scene
