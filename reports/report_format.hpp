#pragma once
// Numbers and labels as the reports print them (any report: fits, FE runs, sweeps).
#include <string>

namespace spifit::reports {

// printf "%.*g" with `digits` significant digits; "n/a" when not finite.
std::string format_significant(double v, int digits = 6);
// printf "%.*f"; "n/a" when not finite; a negative zero ("-0.000") loses its sign.
std::string format_fixed(double v, int decimals);
// A fraction as a percentage with one decimal ("12.5 %"), "< 0.1 %" for tiny positive ones.
std::string format_percent(double fraction);
// "VALUE UNIT"; the unit is left out when empty or "-".
std::string with_unit(const std::string& value, const std::string& unit);
// "NAME [UNIT]" (fallback when the name is empty; no brackets for an empty or "-" unit).
std::string axis_label(const std::string& name, const std::string& unit, const std::string& fallback);

}  // namespace spifit::reports
