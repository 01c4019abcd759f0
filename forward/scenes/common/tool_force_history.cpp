#include "forward/scenes/common/tool_force_history.hpp"

#include "forward/io/binary_archive.hpp"

#include <algorithm>
#include <cmath>

namespace spifit::scene {

void ToolForceHistory::add(const ToolForceSample& s) {
  samples_.push_back(s);
  for (int i = 0; i < 3; ++i)
    if (std::abs(s.force(i)) > std::abs(peak_(i))) peak_(i) = s.force(i);
  max_penetration_ = std::max(max_penetration_, s.penetration);
  max_surface_penetration_ = std::max(max_surface_penetration_, s.surface_penetration);
}

void ToolForceHistory::save(io::BinaryWriter& w) const {
  w.i64(static_cast<std::int64_t>(samples_.size()));
  for (const auto& s : samples_) {
    w.f64(s.travel);
    w.f64(s.time);
    w.vec3(s.centre);
    w.vec3(s.force);
    w.f64(s.penetration);
    w.f64(s.surface_penetration);
    w.i64(s.iterations);
  }
}

void ToolForceHistory::load(io::BinaryReader& r) {
  *this = ToolForceHistory();
  const std::int64_t n = r.i64();
  if (n < 0 || n > 1'000'000'000) throw io::ArchiveError("invalid sample count " + std::to_string(n));
  for (std::int64_t i = 0; i < n; ++i) {
    ToolForceSample s;
    s.travel = r.f64();
    s.time = r.f64();
    s.centre = r.vec3();
    s.force = r.vec3();
    s.penetration = r.f64();
    s.surface_penetration = r.f64();
    s.iterations = static_cast<int>(r.i64());
    add(s);
  }
}

std::optional<std::size_t> peak_sample(const ToolForceHistory& h, int k) {
  std::optional<std::size_t> at;
  double peak = 0.0;
  for (std::size_t i = 0; i < h.samples().size(); ++i) {
    const double f = h.samples()[i].force(k);
    if (std::abs(f) > std::abs(peak)) {
      peak = f;
      at = i;
    }
  }
  return at;
}

std::optional<std::size_t> last_sample(const ToolForceHistory& h) {
  if (h.samples().empty()) return std::nullopt;
  return h.samples().size() - 1;
}

}  // namespace spifit::scene
