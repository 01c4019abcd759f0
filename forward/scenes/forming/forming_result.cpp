#include "forward/scenes/forming/forming_result.hpp"

#include "forward/io/format_text.hpp"
#include "forward/scenes/common/fe_run_summary.hpp"

#include <algorithm>
#include <cstdio>

namespace spifit::scene {

nlohmann::json FormingResult::to_json() const {
  nlohmann::json j = inputs;
  add_status(j);
  add_fe_run_summary(j, run, force, ripple, final_energies, "N mm (= mJ), the modelled sheet only (a half model: half the sheet)");
  j["sections"] = nlohmann::json::array();
  for (const auto& s : sections) j["sections"].push_back({{"point", s.point}, {"file", "sections/section_" + s.point + ".csv"}});
  j["units"] = {{"force", "N, by the sheet on the tool"}, {"length", "mm"}, {"time", "s (travel / feed)"}};
  return j;
}

std::string FormingResult::brief_report() const {
  const Eigen::Vector3d& pk = force.peak();
  return io::format_text("%-16s %-12s peak force (%.2f, %.2f, %.2f) N, max penetration %.4f mm  (%d elements, %d increments, %d iterations, %.2f s)",
                name.c_str(), kind.c_str(), pk.x(), pk.y(), pk.z(), force.max_penetration(), elements, run.counters.increments,
                run.counters.iterations, wall_seconds);
}

ResultCurve FormingResult::path_section(const std::string& point, const std::string& x, const std::string& y) const {
  for (const auto& s : sections) {
    if (s.point != point) continue;
    const std::vector<double> xs = s.nodes.column(x), ys = s.nodes.column(y);
    // Derivatives where the section holds them: x moves, x0 does not; z and the thickness.
    const bool derivatives = s.dz.rows() == static_cast<Eigen::Index>(xs.size()) && (y == "z" || y == "thickness") && (x == "x" || x == "x0");
    return sorted_section_curve(xs, ys, derivatives && x == "x" ? &s.dx : nullptr,
                                derivatives ? (y == "z" ? &s.dz : &s.dthickness) : nullptr);
  }
  return {};
}

}  // namespace spifit::scene
