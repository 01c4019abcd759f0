#include "reports/report_format.hpp"

#include <cmath>
#include <cstdio>

namespace spifit::reports {

std::string format_significant(double v, int digits) {
  if (!std::isfinite(v)) return "n/a";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string format_fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "n/a";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  const std::string s = buf;
  if (s == "-0" || (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-')) return s.substr(1);
  return s;
}

std::string format_percent(double fraction) {
  if (!std::isfinite(fraction)) return "n/a";
  if (fraction > 0 && fraction < 0.0005) return "< 0.1 %";
  return format_fixed(100.0 * fraction, 1) + " %";
}

std::string with_unit(const std::string& value, const std::string& unit) {
  return (unit.empty() || unit == "-") ? value : value + " " + unit;
}

std::string axis_label(const std::string& name, const std::string& unit, const std::string& fallback) {
  std::string s = name.empty() ? fallback : name;
  if (!unit.empty() && unit != "-") s += " [" + unit + "]";
  return s;
}

}  // namespace spifit::reports
