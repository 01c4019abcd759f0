#include "forward/mesh/block_levels.hpp"

#include <algorithm>
#include <stdexcept>

namespace spifit::mesh {
namespace {

struct Grid {
  int nx, ny, sx, sy;
  std::size_t at(int i, int j) const { return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i); }
};

// The largest level whose aligned block around cell (i, j) fits the grid and every cell's limit.
int block_level(const Grid& g, const std::vector<int>& limit, int i, int j) {
  int level = 0;
  for (int k = 1; k <= limit[g.at(i, j)]; ++k) {
    const int s = 1 << k, i0 = (i + g.sx) / s * s - g.sx, j0 = (j + g.sy) / s * s - g.sy;
    if (i0 < 0 || j0 < 0 || i0 + s > g.nx || j0 + s > g.ny) break;
    bool fits = true;
    for (int jj = j0; jj < j0 + s && fits; ++jj)
      for (int ii = i0; ii < i0 + s && fits; ++ii) fits = limit[g.at(ii, jj)] >= k;
    if (!fits) break;
    level = k;
  }
  return level;
}

}  // namespace

bool BlockLevels::block_origin(int nx, int i, int j) const {
  const int s = 1 << level[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i)];
  return (i + shift_x) % s == 0 && (j + shift_y) % s == 0;
}

BlockLevels balanced_block_levels(int nx, int ny, std::vector<int> max_level, int shift_x, int shift_y) {
  if (nx < 1 || ny < 1 || max_level.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) || shift_x < 0 || shift_y < 0)
    throw std::invalid_argument("balanced_block_levels: a level limit per cell of the grid is needed");
  const Grid g{nx, ny, shift_x, shift_y};
  std::vector<int> level(max_level.size(), 0);
  // Limits only go down, so this ends; a sheet needs a few passes.
  for (bool changed = true; changed;) {
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) level[g.at(i, j)] = block_level(g, max_level, i, j);
    changed = false;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int k = level[g.at(i, j)];
        int lowest = k;
        if (i > 0) lowest = std::min(lowest, level[g.at(i - 1, j)]);
        if (i + 1 < nx) lowest = std::min(lowest, level[g.at(i + 1, j)]);
        if (j > 0) lowest = std::min(lowest, level[g.at(i, j - 1)]);
        if (j + 1 < ny) lowest = std::min(lowest, level[g.at(i, j + 1)]);
        if (lowest >= k - 1) continue;
        // Too coarse next to a small block: the whole block may be one level above it at most.
        const int s = 1 << k, i0 = (i + g.sx) / s * s - g.sx, j0 = (j + g.sy) / s * s - g.sy;
        for (int jj = j0; jj < j0 + s; ++jj)
          for (int ii = i0; ii < i0 + s; ++ii) max_level[g.at(ii, jj)] = std::min(max_level[g.at(ii, jj)], lowest + 1);
        changed = true;
      }
  }
  BlockLevels out{std::move(level), shift_x, shift_y, 0};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) out.blocks += out.block_origin(nx, i, j) ? 1 : 0;
  return out;
}

BlockLevels fewest_blocks(int nx, int ny, const std::vector<int>& max_level) {
  const int top = max_level.empty() ? 0 : *std::max_element(max_level.begin(), max_level.end());
  BlockLevels best = balanced_block_levels(nx, ny, max_level);
  for (int sy = 0; sy < (1 << top); ++sy)
    for (int sx = 0; sx < (1 << top); ++sx) {
      BlockLevels b = balanced_block_levels(nx, ny, max_level, sx, sy);
      if (b.blocks < best.blocks) best = std::move(b);
    }
  return best;
}

}  // namespace spifit::mesh
