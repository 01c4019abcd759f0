// The terminal's account of a run with sensitivities (forward/scenes/common/sensitivity_brief.hpp):
// the dominant peak component's derivatives at its own sample, raw with their unit and scaled.
#include "forward/scenes/common/sensitivity_brief.hpp"

#include "forward/scenes/common/sensitivity_log.hpp"
#include "forward/scenes/common/tool_force_history.hpp"

#include <gtest/gtest.h>

namespace spifit::scene {
namespace {

// A result holding a force history and a sensitivity table, as an FE run's.
class TableResult : public SceneResult {
 public:
  ToolForceHistory force;
  io::Series table;
  nlohmann::json to_json() const override { return {}; }
  std::string brief_report() const override { return ""; }
  const ToolForceHistory* tool_force() const override { return &force; }
  const io::Series* force_sensitivities() const override { return table.empty() ? nullptr : &table; }
};

// The run's own layout (SensitivityLog's columns).
io::Series sensitivity_table(const std::vector<std::string>& names, const std::vector<std::string>& units) {
  return io::Series(sensitivity_log_columns(names, units));
}

TEST(SensitivityBrief, TheDominantPeakComponentAtItsOwnSample) {
  TableResult r;
  r.table = sensitivity_table({"swift.K", "contact.friction"}, {"MPa", ""});
  // Fz's peak (-300 N, the largest magnitude of any component) lies in the second sample.
  const double fz[] = {100.0, -300.0, 200.0};
  for (int i = 0; i < 3; ++i) {
    ToolForceSample s;
    s.time = 0.1 * (i + 1);
    s.force = Eigen::Vector3d(40.0 * i, 0.0, fz[i]);
    r.force.add(s);
    const double a = i + 1.0;
    r.table.add_row({s.time, s.time, 1 * a, 2 * a, 3 * a, 180 * a, 360 * a, 540 * a, 4 * a, 5 * a, 6 * a, 0.4 * a, 0.5 * a, 0.6 * a});
  }
  const std::string said = sensitivity_brief(r);
  EXPECT_NE(said.find("sensitivities of the peak Fz (-300.00 N at t = 0.2 s)"), std::string::npos) << said;
  EXPECT_NE(said.find("    swift.K                dFz/dp            6 N/MPa          p dFz/dp       1080 N\n"), std::string::npos) << said;
  EXPECT_NE(said.find("    contact.friction       dFz/dp           12 N              p dFz/dp        1.2 N\n"), std::string::npos) << said;
}

TEST(SensitivityBrief, NothingWithoutATableThatMatchesTheForces) {
  TableResult r;
  ToolForceSample s;
  s.force = Eigen::Vector3d(0.0, 0.0, 10.0);
  r.force.add(s);
  EXPECT_EQ(sensitivity_brief(r), "");  // no sensitivities asked for
  r.table = sensitivity_table({"swift.K"}, {"MPa"});
  r.table.add_row({0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0});
  EXPECT_NE(sensitivity_brief(r), "");
  r.force.add(s);
  EXPECT_EQ(sensitivity_brief(r), "");  // two samples, one row: not this run's table
}

}  // namespace
}  // namespace spifit::scene
