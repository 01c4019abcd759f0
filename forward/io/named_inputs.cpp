#include "forward/io/named_inputs.hpp"

#include "forward/io/input_error.hpp"

#include <algorithm>
#include <cmath>

namespace spifit::io {

bool Range::contains(double v) const {
  if (std::isnan(v)) return false;
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Range::text() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (!has_lo && !has_hi) return "any";
  if (has_lo && !has_hi) return std::string(lo_open ? "> " : ">= ") + format_number(lo);
  if (!has_lo) return std::string(hi_open ? "< " : "<= ") + format_number(hi);
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on the chain of + here.
  std::string out = lo_open ? "(" : "[";
  out += format_number(lo);
  out += ", ";
  out += format_number(hi);
  out += hi_open ? ")" : "]";
  return out;
}

const char* to_string(InputType t) {
  switch (t) {
    case InputType::real: return "number";
    case InputType::integer: return "integer";
    case InputType::boolean: return "true/false";
    case InputType::text: return "text";
    case InputType::list: return "list";
    case InputType::table: return "table";
  }
  return "?";
}

std::string InputInfo::check(double v) const {
  if (type == InputType::text || type == InputType::list || type == InputType::table) return std::string("takes a ") + to_string(type) + " value";
  if (!std::isfinite(v)) return "must be finite";
  if (type == InputType::boolean) return v == 0.0 || v == 1.0 ? std::string() : std::string("takes true (1) or false (0)");
  if (type == InputType::integer && v != std::floor(v)) return "takes integer values";
  if (!range.contains(v)) {
    const std::string t = range.text() + (unit.empty() ? "" : " " + unit);
    return t[0] == '[' || t[0] == '(' ? "must lie in " + t : "must be " + t;
  }
  if (!choices.empty() && std::none_of(choices.begin(), choices.end(), [v](const std::string& c) { return std::stod(c) == v; })) {
    std::string list;  // "45 or 90", "1, 2 or 3"
    for (std::size_t k = 0; k < choices.size(); ++k) list += (k == 0 ? "" : k + 1 == choices.size() ? " or " : ", ") + choices[k];
    return "must be " + list + (unit.empty() ? "" : " " + unit);
  }
  return {};
}

std::string InputInfo::check(const std::string& v) const {
  if (choices.empty() || std::find(choices.begin(), choices.end(), v) != choices.end()) return {};
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
  return "expected " + list;
}

std::string markdown_cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string markdown_reference(const std::vector<InputInfo>& inputs) {
  std::string out = "| key | type | unit | valid values | varied by sweeps and fits | description |\n|---|---|---|---|---|---|\n";
  for (const auto& i : inputs) {
    std::string valid;
    for (const auto& c : i.choices) valid += (valid.empty() ? "`" : ", `") + c + "`";
    if (valid.empty() && (i.type == InputType::real || i.type == InputType::integer)) valid = i.range.text();
    if (valid.empty() && i.type == InputType::text) valid = "text";
    if (i.type == InputType::list || i.type == InputType::table) valid = "see description";
    if (i.type == InputType::boolean) valid = "`true`, `false`";
    out += "| `" + i.name + "` | " + to_string(i.type) + " | " + (i.unit.empty() ? "-" : i.unit) + " | " + valid + " | " +
           (i.variable ? "yes" : "-") + " | " + markdown_cell(i.doc) + " |\n";
  }
  return out;
}

}  // namespace spifit::io
