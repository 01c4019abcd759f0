#include "forward/scenes/forming/path_section_log.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/model/fe_model.hpp"

#include <algorithm>
#include <cmath>

namespace spifit::scene {

PathSectionLog::PathSectionLog(std::vector<std::string> points, std::string scene, const RunFiles& files, int sensitivities)
    : points_(std::move(points)), scene_(std::move(scene)), files_(files), sensitivities_(sensitivities) {}

io::Series PathSectionLog::empty_section() {
  return io::Series({{"x0", "mm"}, {"x", "mm"}, {"y", "mm"}, {"z", "mm"}, {"thickness", "mm"}});
}

void PathSectionLog::at_mark(const Mark& m, const IncrementView& v) {
  if (std::find(points_.begin(), points_.end(), m.name) == points_.end()) return;
  const model::MidSurface mid = v.model.family().mid_surface(v.model);
  std::vector<std::pair<double, int>> line;
  for (int n = 0; n < static_cast<int>(mid.reference.size()); ++n)
    if (std::abs(mid.reference[static_cast<std::size_t>(n)].y()) < 1e-9) line.emplace_back(mid.reference[static_cast<std::size_t>(n)].x(), n);
  std::sort(line.begin(), line.end());
  PathSection s{m.name, empty_section(), {}, {}, {}};
  for (const auto& [x0, n] : line) {
    const Eigen::Vector3d& p = mid.current[static_cast<std::size_t>(n)];
    s.nodes.add_row({x0, p.x(), p.y(), p.z(), mid.thickness[static_cast<std::size_t>(n)]});
  }
  // With sensitivities, the family's mid-surface's.
  if (const int count = v.model.sensitivity_count(); count > 0) {
    s.dx.resize(static_cast<Eigen::Index>(line.size()), count);
    s.dz.resize(static_cast<Eigen::Index>(line.size()), count);
    s.dthickness.resize(static_cast<Eigen::Index>(line.size()), count);
    const model::MidSurfaceSensitivity dm = v.model.family().mid_surface_sensitivity(v.model);
    for (std::size_t i = 0; i < line.size(); ++i) {
      const Eigen::Matrix<double, 3, Eigen::Dynamic>& d = dm.current[static_cast<std::size_t>(line[i].second)];
      s.dx.row(static_cast<Eigen::Index>(i)) = d.row(0);
      s.dz.row(static_cast<Eigen::Index>(i)) = d.row(2);
      s.dthickness.row(static_cast<Eigen::Index>(i)) = dm.thickness.row(line[i].second);
    }
  }
  write_file(s);
  sections_.push_back(std::move(s));
}

void PathSectionLog::write_file(const PathSection& s) const {
  files_.write("sections/section_" + s.point + ".csv",
               "# spifit " + scene_ + ": section y = 0 (mid-surface) at path point " + s.point + "\n" + s.nodes.csv());
}

void PathSectionLog::save(io::BinaryWriter& w) const {
  w.i64(static_cast<std::int64_t>(sections_.size()));
  for (const auto& s : sections_) {
    w.string(s.point);
    w.i64(static_cast<std::int64_t>(s.nodes.size()));
    for (const auto& row : s.nodes.rows()) w.f64s(row);
    if (sensitivities_ > 0) {  // a plain run's state is as it was
      w.matrix(s.dx);
      w.matrix(s.dz);
      w.matrix(s.dthickness);
    }
  }
}

void PathSectionLog::restore(io::BinaryReader& r) {
  sections_.clear();
  const std::int64_t n = r.i64();
  if (n < 0 || n > 100000) throw io::ArchiveError("invalid section count " + std::to_string(n));
  for (std::int64_t i = 0; i < n; ++i) {
    PathSection s{r.string(), empty_section(), {}, {}, {}};
    const std::int64_t rows = r.i64();
    if (rows < 0 || rows > 100'000'000) throw io::ArchiveError("invalid section row count " + std::to_string(rows));
    for (std::int64_t k = 0; k < rows; ++k) {
      std::vector<double> row = r.f64s();
      if (row.size() != s.nodes.columns().size()) throw io::ArchiveError("section row of another width");
      s.nodes.add_row(std::move(row));
    }
    if (sensitivities_ > 0) {
      s.dx = r.matrix();
      s.dz = r.matrix();
      s.dthickness = r.matrix();
      for (const Eigen::MatrixXd* d : {&s.dx, &s.dz, &s.dthickness})
        if (d->rows() != rows || d->cols() != sensitivities_) throw io::ArchiveError("section derivatives of another size");
    }
    sections_.push_back(std::move(s));
  }
}

}  // namespace spifit::scene
