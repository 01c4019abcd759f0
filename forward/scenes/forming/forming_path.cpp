#include "forward/scenes/forming/forming_path.hpp"

#include "forward/toolpath/gcode.hpp"

#include <cmath>
#include <numbers>

namespace spifit::scene {

toolpath::ToolPath gcode_tip_path(const std::string& file) {
  toolpath::ToolPath p = toolpath::read_gcode(file);
  const auto& w = p.waypoints();
  if (w.size() > 2 && w[1].feed == 0.0) return toolpath::ToolPath(std::vector<toolpath::Waypoint>(w.begin() + 1, w.end()), p.rapid_feed());
  return p;
}

toolpath::ToolPath forming_centre_path(const FormingScene& scene) {
  const Eigen::Vector3d lift(0.0, 0.0, 0.5 * scene.thickness + scene.radius);
  if (!scene.gcode.empty()) return gcode_tip_path(scene.gcode).translated(lift);
  std::vector<Eigen::Vector3d> pts;
  for (const auto& p : scene.path) pts.push_back(p.tip + lift);
  return toolpath::ToolPath::from_points(pts, scene.feed);
}

namespace {

std::vector<Mark> corner_marks(const toolpath::ToolPath& path) {
  const auto& w = path.waypoints();
  const std::vector<double> dist = path.waypoint_distances();
  std::vector<Mark> marks;
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  for (std::size_t i = 1; i < w.size(); ++i) {
    const Eigen::Vector3d seg = w[i].position - w[i - 1].position;
    if (seg.norm() < 1e-12) continue;
    const Eigen::Vector3d dir = seg.normalized();
    if (previous.squaredNorm() > 0.0 && previous.dot(dir) < std::cos(15.0 * std::numbers::pi / 180.0) && dist[i - 1] > 0.0)
      marks.push_back({dist[i - 1], "line " + std::to_string(w[i - 1].source_line), 0});
    previous = dir;
  }
  marks.push_back({path.length(), "end", 0});
  return marks;
}

}  // namespace

std::vector<Mark> forming_marks(const FormingScene& scene, const toolpath::ToolPath& centre_path) {
  std::vector<Mark> marks;
  if (!scene.gcode.empty()) {
    marks = corner_marks(centre_path);
  } else {
    const std::vector<double> dist = centre_path.waypoint_distances();
    for (std::size_t i = 1; i < scene.path.size(); ++i) marks.push_back({dist[i], scene.path[i].name, 0});
  }
  // A repeated point adds no travel: the mark of the earlier name stands for it.
  std::vector<Mark> out;
  for (auto& m : marks)
    if (out.empty() ? m.travel > 0.0 : m.travel > out.back().travel) out.push_back(m);
  for (std::size_t i = 0; i < out.size(); ++i) out[i].index = static_cast<int>(i);
  return out;
}

}  // namespace spifit::scene
