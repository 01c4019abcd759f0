#include "forward/scenes/common/sensitivity_brief.hpp"

#include "forward/io/format_text.hpp"
#include "forward/scenes/common/sensitivity_log.hpp"
#include "forward/scenes/common/tool_force_history.hpp"

#include <cmath>

namespace spifit::scene {

std::string sensitivity_brief(const SceneResult& result) {
  const io::Series* table = result.force_sensitivities();
  const ToolForceHistory* force = result.tool_force();
  if (!table || !force || table->size() != force->samples().size()) return "";
  // sensitivities.csv's layout (sensitivity_log.hpp).
  const std::size_t parameters = sensitivity_log_parameters(*table);
  if (parameters == 0) return "";
  const std::vector<io::Column>& columns = table->columns();
  int k = 0;
  for (int c = 1; c < 3; ++c)
    if (std::abs(force->peak()(c)) > std::abs(force->peak()(k))) k = c;
  const auto at = peak_sample(*force, k);
  if (!at) return "";
  const char* component[] = {"Fx", "Fy", "Fz"};
  const ToolForceSample& s = force->samples()[*at];
  std::string out = io::format_text("  sensitivities of the peak %s (%.2f N at t = %.4g s), exact (every increment: sensitivities.csv):\n",
                                    component[k], s.force(k), s.time);
  const std::vector<double>& row = table->row(*at);
  for (std::size_t p = 0; p < parameters; ++p) {
    const std::size_t raw = 2 + 6 * p + static_cast<std::size_t>(k), scaled = raw + 3;
    // The parameter's name from "dFz/d(name)".
    const std::string& title = columns[raw].name;
    const std::size_t open = title.find("/d(");
    const std::string name = open == std::string::npos ? title : title.substr(open + 3, title.size() - open - 4);
    out += io::format_text("    %-22s d%s/dp %12.5g %-14s p d%s/dp %10.4g N\n", name.c_str(), component[k], row[raw], columns[raw].unit.c_str(),
                           component[k], row[scaled]);
  }
  return out;
}

}  // namespace spifit::scene
