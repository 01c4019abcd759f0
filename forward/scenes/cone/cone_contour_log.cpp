#include "forward/scenes/cone/cone_contour_log.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/io/series.hpp"

#include <cstdio>

namespace spifit::scene {

std::vector<ForceSample> polar_samples(const ToolForceHistory& history) {
  std::vector<ForceSample> out;
  out.reserve(history.samples().size());
  for (const auto& s : history.samples()) out.push_back({s.travel, s.force, polar_components(s.force, s.centre)});
  return out;
}

ConeContourLog::ConeContourLog(std::string scene, const ConeTrack& track, const ForceLog& force, const RunFiles& files)
    : scene_(std::move(scene)), track_(track), force_(force), files_(files) {}

void ConeContourLog::at_mark(const Mark& m, const IncrementView& v) {
  contours_ = m.index + 1;
  if (!v.progress) return;
  const ContourSpan& span = track_.contours()[static_cast<std::size_t>(m.index)];
  const Eigen::Vector3d mean = contour_means(track_, polar_samples(force_.history()), m.index + 1).back().polar;
  char buf[240];
  std::snprintf(buf, sizeof buf, "contour %d/%zu (stage %d, contour %d) done, wall %.1f s: central-third mean (Fr, Ftheta, Fz) = (%.1f, %.1f, %.1f) N",
                m.index + 1, track_.contours().size(), span.stage, span.contour, v.wall_seconds, mean.x(), mean.y(), mean.z());
  v.progress({ProgressEvent::Kind::mark, buf, v.travel / track_.path().path.length(), v.lambda});
}

void ConeContourLog::write(WriteReason reason) {
  if (reason == WriteReason::increment) return;
  io::Series t({{"stage", ""}, {"contour", ""}, {"samples", ""}, {"Fx", "N"}, {"Fy", "N"}, {"Fz", "N"}, {"Fr", "N"}, {"Ftheta", "N"}});
  for (const auto& m : means())
    t.add_row({static_cast<double>(m.span.stage), static_cast<double>(m.span.contour), static_cast<double>(m.samples), m.force.x(),
               m.force.y(), m.force.z(), m.polar.x(), m.polar.y()});
  files_.write("contours.csv", "# spifit cone scene " + scene_ + ": mean force over the central third of each completed contour (by travel; thesis §8.3)\n" +
                                   t.csv());
}

void ConeContourLog::save(io::BinaryWriter& w) const { w.i64(contours_); }

void ConeContourLog::restore(io::BinaryReader& r) { contours_ = static_cast<int>(r.i64()); }

}  // namespace spifit::scene
