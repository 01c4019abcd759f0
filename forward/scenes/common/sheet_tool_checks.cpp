#include "forward/scenes/common/sheet_tool_checks.hpp"

#include "forward/io/input_error.hpp"

#include <cmath>
#include <cstdio>

namespace spifit::scene {

using namespace sheet_tool_limits;
using io::format_number;

namespace {

// "1e+30" rather than thirty digits; everyday numbers as they are (2000, 242000, 0.001).
std::string short_number(double v) {
  char buf[32];
  const double a = std::abs(v);
  std::snprintf(buf, sizeof buf, a >= 1e-3 && a < 1e6 ? "%.6g" : "%.3g", v);
  return buf;
}

// The sheet's own stiffness per unit area and unit depth: E / t [N/mm^3].
double sheet_stiffness(const SheetAndTool& s) { return s.card && s.thickness > 0 ? s.card->params.E / s.thickness : std::nan(""); }

}  // namespace

InputViolation sheet_and_tool_error(const SheetAndTool& s) {
  if (s.thickness < kThinnestSheet)
    return {s.thickness_key, format_number(s.thickness),
            "a sheet thinner than one micrometre (" + short_number(kThinnestSheet) + " mm), thinner than any rolled foil: is the unit right (mm)?"};
  if (!s.size_key.empty() && 2.0 * s.tool_radius > s.sheet_size)
    return {s.radius_key, format_number(s.tool_radius),
            "the tool (diameter " + short_number(2.0 * s.tool_radius) + " mm) is larger than the sheet it forms (" + short_number(s.sheet_size) +
                " mm across, " + s.size_key + "): is the unit right (mm)?"};
  if (s.thickness > kThickOverRadiusMax * s.tool_radius)
    return {s.thickness_key, format_number(s.thickness),
            "the sheet is more than " + short_number(kThickOverRadiusMax) + " times thicker than the tool's radius (" + short_number(s.tool_radius) +
                " mm): a shell cannot model a tool this sharp against it"};
  const double k = sheet_stiffness(s);
  if (std::isfinite(k) && s.penalty > kPenaltyMax * k)
    return {"contact.penalty", format_number(s.penalty),
            "a million times stiffer than the sheet itself (E / t = " + short_number(k) +
                " N/mm^3): the sheet's stiffness is lost to round-off beside it; 1e2 to 1e5 N/mm^3 is the usual range (thesis §7.1)"};
  return {};
}

std::vector<std::string> sheet_and_tool_warnings(const SheetAndTool& s) {
  std::vector<std::string> w;
  if (s.thickness < kThinSheet)
    w.push_back("sheet.thickness = " + format_number(s.thickness) + " mm: a foil, thinner than the sheets SPIF is used on (0.5 to 2 mm)");
  if (s.thickness > kThickSheet)
    w.push_back("sheet.thickness = " + format_number(s.thickness) + " mm: a plate rather than a sheet; a shell model is questionable");
  if (s.thickness > kThickOverRadiusOdd * s.tool_radius)
    w.push_back("the sheet (" + format_number(s.thickness) + " mm) is thicker than the tool's radius (" + format_number(s.tool_radius) +
                " mm): the shell's contact on its offset surface is only a rough model of so sharp a tool");
  const double k = sheet_stiffness(s);
  if (std::isfinite(k) && s.penalty < kPenaltyLow * k)
    w.push_back("contact.penalty = " + short_number(s.penalty) + " N/mm^3 is soft against the sheet (E / t = " + short_number(k) +
                " N/mm^3): the tool will sink into the sheet by a good part of its thickness (thesis §7.1: 1e2 left 0.1 mm)");
  if (std::isfinite(k) && s.penalty > kPenaltyHigh * k && s.penalty <= kPenaltyMax * k)
    w.push_back("contact.penalty = " + short_number(s.penalty) + " N/mm^3 is far stiffer than the sheet (E / t = " + short_number(k) +
                " N/mm^3): expect small increments and slow convergence for no gain in accuracy");
  if (s.feed < kSlowFeed || s.feed > kFastFeed)
    w.push_back("tool.feed = " + short_number(s.feed) + " mm/s is beyond any SPIF feed (0.01 to 10000 mm/s): it only sets the times of force.csv "
                "in an implicit run, but is it meant?");
  if (s.card)
    for (const auto& c : material::material_card_warnings(*s.card)) w.push_back("material card " + s.card->name + ": " + c);
  return w;
}

}  // namespace spifit::scene
