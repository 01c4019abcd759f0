#include "forward/scenes/common/scene_result.hpp"

#include "forward/scenes/common/sensitivity_log.hpp"

#include "forward/scenes/common/tool_force_history.hpp"

#include <algorithm>

namespace spifit::scene {

const char* contour_mean_names() { return "fr, ftheta, fz, fx, fy, ftheta_over_fz, fr_over_fz"; }
bool is_contour_mean(const std::string& y) {
  for (const char* n : {"fr", "ftheta", "fz", "fx", "fy", "ftheta_over_fz", "fr_over_fz"})
    if (y == n) return true;
  return false;
}

ResultCurve sorted_section_curve(const std::vector<double>& xs, const std::vector<double>& ys, const Eigen::MatrixXd* dx,
                                 const Eigen::MatrixXd* dy) {
  std::vector<std::size_t> order(xs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return xs[a] < xs[b]; });
  ResultCurve c;
  for (std::size_t i : order) {
    if (!c.x.empty() && !(xs[i] > c.x.back())) return {};  // two nodes at one x: a fold
    c.x.push_back(xs[i]);
    c.y.push_back(ys[i]);
  }
  if (!dy) return c;
  const auto n = static_cast<Eigen::Index>(order.size());
  c.dx = Eigen::MatrixXd::Zero(n, dy->cols());
  c.dy.resize(n, dy->cols());
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto row = static_cast<Eigen::Index>(order[static_cast<std::size_t>(i)]);
    if (dx) c.dx.row(i) = dx->row(row);
    c.dy.row(i) = dy->row(row);
  }
  return c;
}

Eigen::Matrix<double, 3, Eigen::Dynamic> SceneResult::force_sensitivity(std::size_t i) const {
  const io::Series* table = force_sensitivities();
  const ToolForceHistory* force = tool_force();
  if (!table || !force || table->size() != force->samples().size() || i >= table->size()) return Eigen::Matrix<double, 3, Eigen::Dynamic>(3, 0);
  // sensitivities.csv's layout (sensitivity_log.hpp): time, lambda, then per parameter dF and p dF.
  const auto q = static_cast<Eigen::Index>(sensitivity_log_parameters(*table));
  if (q == 0) return Eigen::Matrix<double, 3, Eigen::Dynamic>(3, 0);
  Eigen::Matrix<double, 3, Eigen::Dynamic> d(3, q);
  const std::vector<double>& row = table->row(i);
  for (Eigen::Index k = 0; k < q; ++k)
    for (int c = 0; c < 3; ++c) d(c, k) = row[static_cast<std::size_t>(2 + 6 * k + c)];
  return d;
}

void SceneResult::add_status(nlohmann::json& j) const {
  j["status"] = to_string(status);
  if (!message.empty() && status != RunStatus::ok) j["message"] = message;
  j["warnings"] = warnings;
  j["wall_seconds"] = wall_seconds;
}

}  // namespace spifit::scene
