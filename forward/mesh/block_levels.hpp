#pragma once
// Levels of a quadtree over a structured grid of cells: cell (i, j) (row-major index j nx + i)
// belongs to the aligned square block of 2^k x 2^k cells at level k, the largest level such that
// the block lies inside the grid and no cell of it allows less than k. Blocks are aligned on
// multiples of 2^k of the shifted indices (i + shift_x, j + shift_y). Neighbouring blocks then
// differ by one level at most (2:1 balance): blocks next to much smaller ones are split further.
// Used by square_sheet.hpp to coarsen a sheet away from the tool path.
#include <vector>

namespace spifit::mesh {

struct BlockLevels {
  std::vector<int> level;  // per cell
  int shift_x = 0, shift_y = 0;
  int blocks = 0;
  // Whether cell (i, j) is its block's lower-left cell.
  bool block_origin(int nx, int i, int j) const;
};

// max_level: per cell, the highest level allowed (0: the cell stays as it is). Throws
// std::invalid_argument for sizes that do not match.
BlockLevels balanced_block_levels(int nx, int ny, std::vector<int> max_level, int shift_x = 0, int shift_y = 0);
// The shifts (each below 2^max) that give the fewest blocks, the smallest shift on ties: a grid
// whose cell count is no multiple of the block size leaves its odd rows and columns where the
// cells stay fine anyway. Deterministic.
BlockLevels fewest_blocks(int nx, int ny, const std::vector<int>& max_level);

}  // namespace spifit::mesh
