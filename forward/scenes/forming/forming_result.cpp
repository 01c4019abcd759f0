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
  ResultCurve c;
  for (const auto& s : sections) {
    if (s.point != point) continue;
    const std::vector<double> xs = s.nodes.column(x), ys = s.nodes.column(y);
    std::vector<std::size_t> order(xs.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return xs[a] < xs[b]; });
    for (std::size_t i : order) {
      if (!c.x.empty() && !(xs[i] > c.x.back())) return {};  // two nodes at one x: a fold
      c.x.push_back(xs[i]);
      c.y.push_back(ys[i]);
    }
    // Derivatives where the section holds them: x moves, x0 does not; z and the thickness.
    if (s.dz.rows() == static_cast<Eigen::Index>(xs.size()) && (y == "z" || y == "thickness") && (x == "x" || x == "x0")) {
      const Eigen::Index n = static_cast<Eigen::Index>(order.size());
      c.dx = Eigen::MatrixXd::Zero(n, s.dz.cols());
      c.dy.resize(n, s.dz.cols());
      for (Eigen::Index i = 0; i < n; ++i) {
        const auto row = static_cast<Eigen::Index>(order[static_cast<std::size_t>(i)]);
        if (x == "x") c.dx.row(i) = s.dx.row(row);
        c.dy.row(i) = y == "z" ? s.dz.row(row) : s.dthickness.row(row);
      }
    }
    break;
  }
  return c;
}

}  // namespace spifit::scene
