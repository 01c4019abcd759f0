#pragma once
// Tool-centre paths as CSV point lists:
//   # comment lines and blank lines are skipped anywhere; a UTF-8 BOM is tolerated
//   x [mm], y [mm], z [mm], feed [mm/s]     <- header: x, y, z required, feed optional
//   -50, 0, -5, 10                           <- one waypoint per row
// Column names are case-insensitive, in any order; a unit in brackets may follow a name and
// must be mm for x, y, z and mm/s for feed (no conversion is done, so any other unit is an
// error). Feed is the speed used to reach the row's point (0 = rapid); an empty feed cell, a
// row that leaves out a last feed column, or a file without a feed column gives default_feed.
// Errors (io::InputError, key "line N", 1-based): unknown, repeated or missing column, bad
// unit, wrong cell count, non-numeric or negative value, fewer than 2 points.
#include "forward/toolpath/tool_path.hpp"

#include <string>

namespace spifit::toolpath {

// Reads a CSV tool path (rapid segments run at ToolPath's default rapid feed). Throws
// std::invalid_argument when default_feed is negative or not finite.
ToolPath read_path_csv(const std::string& file, double default_feed);

}  // namespace spifit::toolpath
