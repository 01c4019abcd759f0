#pragma once
// Is a sheet-and-tool scene physically plausible? Checked when a scene is read, before anything
// runs, in a forming engineer's words (docs/guide/running-scenes.md, "Plausibility checks"):
// errors for what cannot run (a sheet thinner than any metal foil, a tool larger than the sheet,
// a penalty that drowns the sheet's own stiffness), warnings for what is legal but odd.
#include "forward/material/material_card.hpp"
#include "forward/scenes/common/scene_tables.hpp"

#include <string>
#include <vector>

namespace spifit::scene {

struct SheetAndTool {
  double thickness = 0.0;    // mm
  double sheet_size = 0.0;   // the sheet's smallest lateral extent: a square's side, a disc's diameter [mm]
  double tool_radius = 0.0;  // mm
  double penalty = 0.0;      // contact penalty [N/mm^3]
  double feed = 0.0;         // mm/s
  const material::MaterialCard* card = nullptr;
  // The scene's keys for the thickness, the sheet's size and the tool radius (errors name them).
  std::string thickness_key = "sheet.thickness", size_key, radius_key = "tool.radius";
};

// Limits of the checks (decisions.md, "Plausibility checks", says why each).
namespace sheet_tool_limits {
constexpr double kThinnestSheet = 1e-3;      // mm: one micrometre, below any rolled foil
constexpr double kThinSheet = 0.05;          // mm: warning below (foils)
constexpr double kThickSheet = 10.0;         // mm: warning above (plate, not sheet)
constexpr double kThickOverRadiusOdd = 1.0;  // t / R: warning above
constexpr double kThickOverRadiusMax = 4.0;  // t / R: error above (the tool is a point for the sheet)
// Penalty against the sheet's own stiffness scale E / t [N/mm^3].
constexpr double kPenaltyLow = 1e-3;    // warning below: the tool sinks into the sheet by a good part of t
constexpr double kPenaltyHigh = 1e3;    // warning above: the tangent is dominated by the contact
constexpr double kPenaltyMax = 1e6;     // error above: the tangent loses the sheet's stiffness to round-off
constexpr double kSlowFeed = 0.01;      // mm/s: warning below
constexpr double kFastFeed = 1e4;       // mm/s: warning above
}  // namespace sheet_tool_limits

// What cannot run (the first found), or nothing.
InputViolation sheet_and_tool_error(const SheetAndTool& s);
// What is legal but odd, each in one sentence (the card's oddities included).
std::vector<std::string> sheet_and_tool_warnings(const SheetAndTool& s);

}  // namespace spifit::scene
