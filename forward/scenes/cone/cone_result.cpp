#include "forward/scenes/cone/cone_result.hpp"

#include "forward/scenes/cone/cone_sensitivities.hpp"

#include "forward/io/format_text.hpp"
#include "forward/scenes/common/fe_run_summary.hpp"

#include <algorithm>
#include <cmath>
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

namespace {

double point_value(const SectionPoint& p, const std::string& c) {
  if (c == "r") return p.r;
  if (c == "r0") return p.r0;
  if (c == "z") return p.z;
  return p.thickness;
}

double contour_mean_value(const ContourMean& m, const std::string& y) {
  if (y == "fr") return m.polar.x();
  if (y == "ftheta") return m.polar.y();
  if (y == "fz") return m.polar.z();
  if (y == "fx") return m.force.x();
  if (y == "fy") return m.force.y();
  if (y == "ftheta_over_fz") return m.polar.y() / m.polar.z();
  return m.polar.x() / m.polar.z();  // fr_over_fz
}

}  // namespace

ResultCurve ConeResult::contour_section(int contour, const std::string& x, const std::string& y) const {
  ResultCurve c;
  if (contour < 1 || static_cast<std::size_t>(contour) > section_profiles.size()) return c;
  const ConeSection& s = section_profiles[static_cast<std::size_t>(contour - 1)];
  std::vector<double> xs, ys;
  for (const SectionPoint& p : s.points) {
    xs.push_back(point_value(p, x));
    ys.push_back(point_value(p, y));
  }
  // Derivatives where the section holds them: r moves, r0 does not; z and the thickness.
  const bool derivatives = s.dz.rows() == static_cast<Eigen::Index>(xs.size()) && (y == "z" || y == "thickness") && (x == "r" || x == "r0");
  return sorted_section_curve(xs, ys, derivatives && x == "r" ? &s.dr : nullptr,
                              derivatives ? (y == "z" ? &s.dz : &s.dthickness) : nullptr);
}

namespace {

// d/dp of contour_mean_value from the mean's derivatives.
Eigen::RowVectorXd contour_mean_derivative(const ContourMean& m, const SteadyStateDerivatives& d, const std::string& y) {
  if (y == "fr") return d.polar.row(0);
  if (y == "ftheta") return d.polar.row(1);
  if (y == "fz") return d.polar.row(2);
  if (y == "fx") return d.force.row(0);
  if (y == "fy") return d.force.row(1);
  const int k = y == "ftheta_over_fz" ? 1 : 0;
  const double fz = m.polar.z();
  return d.polar.row(k) / fz - m.polar(k) / (fz * fz) * d.polar.row(2);
}

}  // namespace

ResultCurve ConeResult::contour_means(const std::string& y) const {
  ResultCurve c;
  std::vector<Eigen::RowVectorXd> dy;
  for (std::size_t i = 0; i < contours.size(); ++i) {
    c.x.push_back(static_cast<double>(i + 1));
    c.y.push_back(contour_mean_value(contours[i], y));
    const int contour = static_cast<int>(i) + 1;
    if (const auto d = steady_state_sensitivity(*this, contour, contour)) dy.push_back(contour_mean_derivative(contours[i], *d, y));
  }
  if (!dy.empty() && dy.size() == contours.size()) {  // a contour without samples has none
    c.dy.resize(static_cast<Eigen::Index>(dy.size()), dy.front().size());
    for (std::size_t i = 0; i < dy.size(); ++i) c.dy.row(static_cast<Eigen::Index>(i)) = dy[i];
  }
  return c;
}

}  // namespace spifit::scene
