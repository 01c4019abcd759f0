#include "forward/scenes/cone/cone_observable_log.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/io/format_text.hpp"
#include "forward/io/series_archive.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/mesh/mesh.hpp"
#include "forward/scenes/cone/cone_scene.hpp"
#include "forward/scenes/cone/element_history.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numbers>

namespace spifit::scene {
namespace {

using json = nlohmann::json;

double stage_wall_angle(const ConeScene& s, int stage) {
  const std::size_t i = static_cast<std::size_t>(std::max(1, stage) - 1);
  return s.stages[std::min(i, s.stages.size() - 1)].wall_angle_deg;
}

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

const std::vector<std::string> kSectionColumns{"stage", "contour", "wall_angle [deg]", "plateau_nodes", "plateau_thickness [mm]",
                                               "sine_law_thickness [mm]", "plateau_over_sine_law", "min_thickness [mm]",
                                               "min_thickness_r0 [mm]", "min_thickness_depth [mm]", "max_elongation", "centre_z [mm]",
                                               "centre_depth [mm]"};
const std::vector<std::string> kStageColumns{"stage", "wall_angle [deg]", "travel [mm]", "centre_z [mm]", "centre_depth [mm]",
                                             "max_elongation"};

// A section point's fields in a fixed order (checkpoints).
constexpr std::size_t kPointFields = 13;
std::vector<double> point_fields(const SectionPoint& p) {
  return {p.r0, p.r, p.theta_deg, p.z, p.thickness, p.r_top, p.z_top, p.r_bottom, p.z_bottom, p.depth, p.wall_angle_deg, p.u_theta, p.dtheta_deg};
}
SectionPoint point_from(const double* f) {
  SectionPoint p;
  for (double* x : {&p.r0, &p.r, &p.theta_deg, &p.z, &p.thickness, &p.r_top, &p.z_top, &p.r_bottom, &p.z_bottom, &p.depth, &p.wall_angle_deg,
                    &p.u_theta, &p.dtheta_deg})
    *x = *f++;
  return p;
}

void save_profiles(io::BinaryWriter& w, const std::vector<ConeSection>& profiles) {
  w.i64(static_cast<std::int64_t>(profiles.size()));
  for (const auto& s : profiles) {
    w.i64(s.stage);
    w.i64(s.contour);
    std::vector<double> f;
    for (const auto& p : s.points)
      for (double x : point_fields(p)) f.push_back(x);
    w.f64s(f);
  }
}

void load_profiles(io::BinaryReader& r, std::vector<ConeSection>* profiles) {
  profiles->clear();
  const std::int64_t n = r.i64();
  if (n < 0 || n > 1'000'000) throw io::ArchiveError("invalid section count " + std::to_string(n));
  for (std::int64_t i = 0; i < n; ++i) {
    ConeSection s;
    s.stage = static_cast<int>(r.i64());
    s.contour = static_cast<int>(r.i64());
    const std::vector<double> f = r.f64s();
    if (f.size() % kPointFields != 0) throw io::ArchiveError("section points of another width");
    for (std::size_t k = 0; k < f.size(); k += kPointFields) s.points.push_back(point_from(&f[k]));
    profiles->push_back(std::move(s));
  }
}

}  // namespace

std::vector<double> stage_end_distances(const toolpath::ConePath& path) {
  const std::vector<double> dist = path.path.waypoint_distances();
  std::vector<double> ends;
  for (std::size_t i = 0; i < path.segments.size() && i < dist.size(); ++i) {
    const auto& seg = path.segments[i];
    if (seg.move != toolpath::ConeMove::retract) continue;
    const std::size_t k = static_cast<std::size_t>(seg.stage - 1);
    if (ends.size() <= k) ends.resize(k + 1, 0.0);
    ends[k] = std::max(ends[k], dist[i]);
  }
  if (ends.empty()) ends.push_back(dist.empty() ? 0.0 : dist.back());
  return ends;
}

ConeObservableLog::ConeObservableLog(const ConeScene& scene, const model::FeModel& model, const mesh::Mesh& mid_surface, const ConeTrack& track,
                                     const RunFiles& files)
    : scene_(scene), model_(model), mid_surface_(mid_surface), track_(track), files_(files),
      line_(radial_line_nodes(mid_surface, section_angle_deg(scene.pie_angle))), stage_ends_(stage_end_distances(track.path())),
      // The run's shells use the scene's thickness rule and points (element_history_row checks
      // the count against the element's layers).
      rule_(element::make_thickness_rule(scene.thickness_rule, scene.thickness_points)),
      section_rows_(io::parse_columns(kSectionColumns)), stage_rows_(io::parse_columns(kStageColumns)),
      history_rows_(io::parse_columns(element_history_columns(scene.thickness_points))) {
  const auto axis = mid_surface.node_sets.find("axis");
  if (axis != mid_surface.node_sets.end() && !axis->second.empty()) centre_node_ = axis->second.front();
  if (scene.history_element) {
    if (!dynamic_cast<const model::ShellModel*>(&model))
      throw std::invalid_argument("the element history (output.history_element) is the shell's; the model has " + model.family().name() +
                                  " elements");
    history_element_ = nearest_element(mid_surface, scene.history_element->r, scene.history_element->theta_deg);
  }
}

std::vector<SectionNode> ConeObservableLog::section_nodes(const model::MidSurface& mid) const {
  std::vector<SectionNode> nodes;
  for (int n : line_) {
    const std::size_t i = static_cast<std::size_t>(n);
    nodes.push_back({mid.reference[i], mid.current[i], mid.director[i], mid.thickness[i]});
  }
  return nodes;
}

double ConeObservableLog::centre_z(const model::MidSurface& mid) const {
  return centre_node_ >= 0 ? mid.current[static_cast<std::size_t>(centre_node_)].z() : std::numeric_limits<double>::quiet_NaN();
}

void ConeObservableLog::after_increment(const IncrementView& v) {
  const double travel = v.travel;
  if (history_element_ >= 0) {
    const auto& shell = static_cast<const model::ShellModel&>(model_);  // checked at construction
    history_rows_.add_row(element_history_values(travel, v.lambda, element_history_row(shell, history_element_, rule_)));
  }
  // Stage ends (the end of the stage's retract; the last stage ends with the path).
  while (stage_rows_.size() < stage_ends_.size() && travel >= stage_ends_[stage_rows_.size()] - 1e-9) {
    const int stage = static_cast<int>(stage_rows_.size()) + 1;
    const model::MidSurface mid = model_.family().mid_surface(model_);
    const double z = centre_z(mid);
    double max_ratio = 0.0;
    for (const auto& e : radial_elongation(section_nodes(mid))) max_ratio = std::max(max_ratio, e.ratio);
    stage_rows_.add_row({static_cast<double>(stage), stage_wall_angle(scene_, stage), travel, z, -z, max_ratio});
    if (model_.sensitivity_count() > 0 && centre_node_ >= 0)
      depth_sensitivities_.push_back(-model_.family().mid_surface_sensitivity(model_).current[static_cast<std::size_t>(centre_node_)].row(2));
  }
}

// The section nodes are the mid-surface's: r = |(x, y)| moves with (x dx + y dy) / r (zero on the
// axis, whose in-plane translations are tied to zero).
void ConeObservableLog::add_section_sensitivities(const model::MidSurface& mid, ConeSection* section) const {
  const int count = model_.sensitivity_count();
  const auto n = static_cast<Eigen::Index>(line_.size());
  section->dr.resize(n, count);
  section->dz.resize(n, count);
  section->dthickness.resize(n, count);
  const model::MidSurfaceSensitivity dm = model_.family().mid_surface_sensitivity(model_);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto node = static_cast<std::size_t>(line_[static_cast<std::size_t>(i)]);
    const Eigen::Vector3d& x = mid.current[node];
    const Eigen::Matrix<double, 3, Eigen::Dynamic>& d = dm.current[node];
    const double r = std::hypot(x.x(), x.y());
    section->dr.row(i) = r > 0.0 ? Eigen::RowVectorXd((x.x() * d.row(0) + x.y() * d.row(1)) / r) : Eigen::RowVectorXd::Zero(count);
    section->dz.row(i) = d.row(2);
    section->dthickness.row(i) = dm.thickness.row(static_cast<Eigen::Index>(node));
  }
}

void ConeObservableLog::at_mark(const Mark& m, const IncrementView& v) {
  (void)v;
  const ContourSpan& span = track_.contours()[static_cast<std::size_t>(m.index)];
  const model::MidSurface mid = model_.family().mid_surface(model_);
  const std::vector<SectionNode> nodes = section_nodes(mid);
  const double theta0 = section_angle_deg(scene_.pie_angle);
  const std::vector<SectionPoint> points = radial_section(nodes, theta0, scene_.thickness);
  const std::vector<RadialEdge> edges = radial_elongation(nodes);
  const double wall = stage_wall_angle(scene_, span.stage);
  const SectionSummary s = summarise_section(points, edges, wall, scene_.thickness);
  char name[64];
  std::snprintf(name, sizeof name, "sections/section_s%d_c%03d.csv", span.stage, span.contour);
  files_.write(name, io::format_text("# spifit cone scene %s: section at theta0 = %.6g deg after stage %d, contour %d: mid-surface, "
                                     "top/bottom = mid +- h/2 along the nodal director, depth of the top surface, wall angle, twist\n",
                                     scene_.name.c_str(), theta0, span.stage, span.contour) +
                         section_csv(points));
  std::snprintf(name, sizeof name, "sections/elongation_s%d_c%03d.csv", span.stage, span.contour);
  files_.write(name, io::format_text("# spifit cone scene %s: radial elongation of the section's element edges after stage %d, contour %d\n",
                                     scene_.name.c_str(), span.stage, span.contour) +
                         elongation_csv(edges));
  profiles_.push_back({span.stage, span.contour, points, {}, {}, {}});
  if (model_.sensitivity_count() > 0) add_section_sensitivities(mid, &profiles_.back());
  const double z = centre_z(mid);
  section_rows_.add_row({static_cast<double>(span.stage), static_cast<double>(span.contour), wall, static_cast<double>(s.plateau_nodes),
                           s.plateau_thickness, s.sine_law_thickness, s.plateau_thickness / s.sine_law_thickness, s.min_thickness,
                           s.min_thickness_r0, s.min_thickness_depth, s.max_elongation, z, -z});
}

void ConeObservableLog::write(WriteReason reason) {
  const bool now = reason == WriteReason::mark || reason == WriteReason::end;
  if (!now && stage_rows_.size() == stages_written_) return;
  stages_written_ = stage_rows_.size();
  const std::string head = "# spifit cone scene " + scene_.name;
  files_.write("sections.csv", head + ": per section (after each contour): wall-thickness plateau (nodes whose wall angle is within "
                                         "5 deg of the cone's) vs the sine law t0 sin(90 - alpha), thinnest node, largest radial "
                                         "elongation, part centre (axis node, mid-surface)\n" + section_rows_.csv());
  files_.write("stages.csv", head + ": at the end of each stage (end of its retract; thesis Fig. 8.16): part centre = axis node, "
                                       "mid-surface; depth = -z\n" + stage_rows_.csv());
  if (history_element_ >= 0) {
    const Eigen::Vector3d c = mid_surface_.centroid(history_element_);
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  ": element %d (initial centroid r = %.6g mm, theta = %.6g deg), after every increment; Green strains and curvatures in "
                  "the initial polar frame at the element centre, layer stresses (Gauss-point mean), bottom (L1) to top\n",
                  history_element_, c.head<2>().norm(), std::atan2(c.y(), c.x()) * 180.0 / std::numbers::pi);
    files_.write("history.csv", head + buf + history_rows_.csv());
  }
}

json ConeObservableLog::summary() const {
  json j;
  j["section_angle_deg"] = section_angle_deg(scene_.pie_angle);
  j["last_section"] = nullptr;
  if (!section_rows_.empty()) {
    json row;
    for (std::size_t i = 0; i < kSectionColumns.size(); ++i)
      row[kSectionColumns[i].substr(0, kSectionColumns[i].find(' '))] = finite_or_null(section_rows_.rows().back()[i]);
    j["last_section"] = row;
  }
  j["stages"] = json::array();
  for (const auto& r : stage_rows_.rows())
    j["stages"].push_back({{"stage", static_cast<int>(r[0])}, {"wall_angle", r[1]}, {"centre_z", finite_or_null(r[3])},
                           {"centre_depth", finite_or_null(r[4])}, {"max_elongation", r[5]}});
  if (history_element_ >= 0) {
    const Eigen::Vector3d c = mid_surface_.centroid(history_element_);
    j["history_element"] = {{"element", history_element_},
                            {"requested", {{"r", scene_.history_element->r}, {"theta", scene_.history_element->theta_deg}}},
                            {"centroid_r", c.head<2>().norm()},
                            {"centroid_theta", std::atan2(c.y(), c.x()) * 180.0 / std::numbers::pi}};
  }
  return j;
}

void ConeObservableLog::save(io::BinaryWriter& w) const {
  io::save_series_rows(w, section_rows_);
  io::save_series_rows(w, stage_rows_);
  io::save_series_rows(w, history_rows_);
  save_profiles(w, profiles_);
  if (model_.sensitivity_count() > 0) {  // a plain run's state is as it was
    w.i64(static_cast<std::int64_t>(depth_sensitivities_.size()));
    for (const Eigen::RowVectorXd& d : depth_sensitivities_) w.vector(d.transpose());
    for (const ConeSection& p : profiles_)
      for (const Eigen::MatrixXd* d : {&p.dr, &p.dz, &p.dthickness}) w.matrix(*d);
  }
}

void ConeObservableLog::restore(io::BinaryReader& r) {
  io::load_series_rows(r, &section_rows_, "observable");
  io::load_series_rows(r, &stage_rows_, "observable");
  io::load_series_rows(r, &history_rows_, "observable");
  load_profiles(r, &profiles_);
  depth_sensitivities_.clear();
  if (const int count = model_.sensitivity_count(); count > 0) {
    const std::int64_t n = r.i64();
    if (n < 0 || n > static_cast<std::int64_t>(stage_rows_.size())) throw io::ArchiveError("invalid count of centre depth derivatives " + std::to_string(n));
    for (std::int64_t i = 0; i < n; ++i) {
      const Eigen::VectorXd d = r.vector();
      if (d.size() != count) throw io::ArchiveError("centre depth derivatives of another size");
      depth_sensitivities_.push_back(d.transpose());
    }
    for (ConeSection& p : profiles_)
      for (Eigen::MatrixXd* d : {&p.dr, &p.dz, &p.dthickness}) {
        *d = r.matrix();
        if (d->rows() != static_cast<Eigen::Index>(p.points.size()) || d->cols() != count) throw io::ArchiveError("section derivatives of another size");
      }
  }
}

}  // namespace spifit::scene
