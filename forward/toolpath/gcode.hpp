#pragma once
// G-code reader for SPIF tool paths (the tool centre; no cutter compensation or tool length
// offsets). Supported, with the modal semantics of real controllers:
//   G00 rapid, G01 linear at F, G02/G03 clockwise / counter-clockwise arcs in the XY plane
//   (centre by I J, incremental from the start point, or by radius R: R > 0 the shorter arc,
//   R < 0 the longer one; Z may change linearly along the arc = helix; a full circle is
//   end == start with I/J), G17 (XY plane), G20 inch / G21 mm, G90 absolute / G91
//   incremental, G94 feed per minute; F feed in units/min; X Y Z.
//   Motion mode and F persist; a line with only coordinates repeats the last motion; missing
//   axes keep their value. Mode words (G20/G21, G90/G91, F) act before the move on the same
//   line. N words, S words, T words, M00-M09 and M30 are ignored, and so are blank lines,
//   '%' lines, (comments) and '; comments' to the end of the line.
// Anything else (G41, G43, G28, G18, unknown letters, malformed numbers, two codes of one
// modal group on a line, a word twice on a line, a fed move before any F, an arc whose end is
// off its circle by more than 1e-3 mm x max(1, radius), radius 0) is an io::InputError with
// key "line N" (1-based) and the offending word (or the line) as value.
// Arcs become straight segments whose chord error (sagitta) is <= arc_tolerance; every
// generated point carries the arc's source line and feed. Waypoint 0 is options.start.
#include "forward/toolpath/tool_path.hpp"

#include <string>

namespace spifit::toolpath {

struct GcodeOptions {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // tool position before the first move, mm
  double rapid_feed = 100.0;                        // mm/s for G00
  double arc_tolerance = 0.005;                     // mm chord error for G02/G03
};

// Reads and parses a G-code file; an unreadable file is InputError(file, "", "", "cannot read
// file"). Throws std::invalid_argument on meaningless options.
ToolPath read_gcode(const std::string& file, const GcodeOptions& o = {});

// Parses G-code text; file_name_for_errors is the FILE of the error messages.
ToolPath parse_gcode(const std::string& text, const std::string& file_name_for_errors,
                     const GcodeOptions& o = {});

}  // namespace spifit::toolpath
