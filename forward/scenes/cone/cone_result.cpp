#include "forward/scenes/cone/cone_result.hpp"

#include "forward/io/format_text.hpp"
#include "forward/scenes/common/fe_run_summary.hpp"

#include <cstdio>

namespace spifit::scene {

Eigen::Vector3d ConeResult::final_polar_force() const {
  if (force.empty()) return Eigen::Vector3d::Zero();
  return polar_components(force.samples().back().force, force.samples().back().centre);
}

nlohmann::json ConeResult::to_json() const {
  nlohmann::json j = inputs;
  add_status(j);
  add_fe_run_summary(j, run, force, ripple, final_energies, "N mm (= mJ), the modelled pie only");
  j["contours_total"] = contours_total;
  j["contours_completed"] = run.marks_reached;
  j["peak_polar_force"] = vector_json(peak_polar);
  j["final_polar_force"] = vector_json(final_polar_force());
  j["units"] = {{"force", "N, by the sheet on the real tool (pies: not scaled by 360 / pie_angle)"},
                {"polar_force", "(r, theta, z) at the tool centre's polar angle"},
                {"length", "mm"},
                {"time", "s (travel / feed)"}};
  j["observables"] = observables;
  if (steady_state) {
    const SteadyState& ss = *steady_state;
    j["steady_state"] = {{"contours", {ss.from, ss.to}},
                         {"contours_used", ss.contours},
                         {"force", vector_json(ss.force)},
                         {"polar_force", vector_json(ss.polar)},
                         {"fr_over_fz", ss.polar.x() / ss.polar.z()},
                         {"definition", "mean of the central-third contour means of the completed contours in the range (thesis §9.3)"}};
  }
  j["contour_wall_seconds"] = run.mark_wall_seconds;
  // A cone's marks are its contours: besides every FE run's every_marks and resumed_at_mark,
  // summary.json has them under these names too, since both are documented
  // (docs/reference/file-formats.md, "Cone scene"; docs/design/architecture.md, "Checkpoints and resume").
  j["checkpoints"]["every_contours"] = run.checkpoints.every_marks;
  if (run.resumed_at_mark >= 0) j["resumed_at_contour"] = run.resumed_at_mark;
  return j;
}

std::string ConeResult::brief_report() const {
  const Eigen::Vector3d& pk = force.peak();
  const Eigen::Vector3d fp = final_polar_force();
  return io::format_text(
                "%-16s %-12s peak force (%.2f, %.2f, %.2f) N, final (Fr, Ftheta, Fz) (%.2f, %.2f, %.2f) N, %d/%d contours  (%d elements, %d increments, %d iterations, %.2f s)",
                name.c_str(), "cone", pk.x(), pk.y(), pk.z(), fp.x(), fp.y(), fp.z(), run.marks_reached, contours_total, elements,
                run.counters.increments, run.counters.iterations, wall_seconds);
}

}  // namespace spifit::scene
