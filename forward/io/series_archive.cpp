#include "forward/io/series_archive.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace spifit::io {

void save_series_rows(BinaryWriter& w, const Series& s) {
  w.i64(static_cast<std::int64_t>(s.size()));
  for (const auto& row : s.rows()) w.f64s(row);
}

void load_series_rows(BinaryReader& r, Series* s, const std::string& what) {
  s->clear();
  const std::int64_t n = r.i64();
  if (n < 0 || n > 1'000'000'000) throw ArchiveError("invalid " + what + " row count " + std::to_string(n));
  for (std::int64_t i = 0; i < n; ++i) {
    std::vector<double> row = r.f64s();
    if (row.size() != s->columns().size()) throw ArchiveError(what + " row of another width");
    s->add_row(std::move(row));
  }
}

}  // namespace spifit::io
