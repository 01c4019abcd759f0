#include "inverse/experiments/measurement.hpp"

#include "forward/io/input_error.hpp"

#include <cmath>
#include <limits>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace spifit::inverse {

using io::InputError;

namespace {
using io::trim;
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}
}  // namespace

const std::vector<double>& MeasurementTable::column(const std::string& name) const {
  const auto it = columns.find(name);
  if (it == columns.end()) {
    std::string have;
    for (const auto& n : names) have += (have.empty() ? "" : ", ") + n;
    throw InputError(file, "column", name, "no such column (columns: " + have + ")");
  }
  return it->second;
}

MeasurementTable read_measurement_csv(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, "", "", "measurement file not found");
  std::ifstream in(path);
  MeasurementTable t;
  t.file = path;
  std::string line;
  int lineno = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++lineno;
    if (lineno == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line = line.substr(3);  // UTF-8 byte-order mark
    std::string s = trim(line);
    if (const std::size_t bad = io::first_non_text(s); bad != std::string::npos) {
      char byte[8];
      std::snprintf(byte, sizeof byte, "\\x%02X", static_cast<unsigned>(static_cast<unsigned char>(s[bad])));
      throw InputError(path, "line " + std::to_string(lineno), s,
                       std::string("not text (byte ") + byte + " at position " + std::to_string(bad + 1) +
                           "): a measurement file is CSV text, a header naming the columns and rows of numbers");
    }
    // Spreadsheet exports end every row with a comma: drop one empty last cell.
    if (!s.empty() && s.back() == ',' && s[0] != '#') s.pop_back();
    if (s.empty()) continue;
    if (s[0] == '#') {
      t.comments.push_back(trim(s.substr(1)));
      continue;
    }
    const auto cells = split(s);
    if (!header) {
      for (const auto& c : cells) {
        std::string name = c, unit;
        const auto br = c.find('[');
        if (br != std::string::npos) {
          const auto close = c.find(']', br);
          if (close == std::string::npos) throw InputError(path, "line " + std::to_string(lineno), c, "unit bracket not closed");
          name = trim(c.substr(0, br));
          unit = trim(c.substr(br + 1, close - br - 1));
        }
        if (name.empty()) throw InputError(path, "line " + std::to_string(lineno), c, "empty column name");
        if (t.columns.count(name)) throw InputError(path, "line " + std::to_string(lineno), name, "duplicate column name");
        t.names.push_back(name);
        t.units[name] = unit;
        t.columns[name] = {};
      }
      header = true;
      continue;
    }
    if (cells.size() != t.names.size()) {
      throw InputError(path, "line " + std::to_string(lineno), s,
                       "expected " + std::to_string(t.names.size()) + " values, found " + std::to_string(cells.size()));
    }
    for (std::size_t i = 0; i < cells.size(); ++i) {
      char* end = nullptr;
      const double v = std::strtod(cells[i].c_str(), &end);
      if (cells[i].empty() || end != cells[i].c_str() + cells[i].size() || !std::isfinite(v)) {
        throw InputError(path, "line " + std::to_string(lineno) + ", column " + t.names[i], cells[i], "not a finite number");
      }
      t.columns[t.names[i]].push_back(v);
    }
  }
  if (!header) throw InputError(path, "", "", "no header row");
  if (t.rows() == 0) throw InputError(path, "", "", "no data rows");
  return t;
}

std::string resolve_path(const std::string& base_file, const std::string& path) {
  std::filesystem::path q(path);
  if (q.is_relative()) q = std::filesystem::path(base_file).parent_path() / q;
  return q.lexically_normal().string();
}

namespace {

bool dimensionless(const std::string& u) { return u.empty() || u == "-"; }

// The factor from unit `from` to unit `to`, NaN when they do not convert.
double unit_factor(const std::string& from, const std::string& to) {
  if (from == to || (dimensionless(from) && dimensionless(to))) return 1.0;
  struct Conversion {
    const char* from;
    const char* to;  // "-": dimensionless
    double factor;
  };
  static const Conversion kConversions[] = {
      {"%", "-", 0.01},  {"kN", "N", 1e3},    {"GPa", "MPa", 1e3}, {"kPa", "MPa", 1e-3}, {"Pa", "MPa", 1e-6}, {"N/mm^2", "MPa", 1.0},
      {"N/mm2", "MPa", 1.0}, {"um", "mm", 1e-3}, {"µm", "mm", 1e-3}, {"cm", "mm", 10.0},  {"m", "mm", 1e3},   {"ms", "s", 1e-3},
      {"min", "s", 60.0},
  };
  const std::string target = dimensionless(to) ? "-" : to;
  for (const Conversion& c : kConversions)
    if (from == c.from && target == c.to) return c.factor;
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

void convert_column(MeasurementTable& t, const std::string& column, const std::string& unit) {
  auto& values = t.columns.at(column);  // callers read the column first (column() names a missing one)
  std::string& own = t.units[column];
  if (own.empty()) {
    own = unit;
    return;
  }
  const double f = unit_factor(own, unit);
  if (!std::isfinite(f)) {
    throw InputError(t.file, "column " + column, own,
                     "a unit spifit does not convert to " + (dimensionless(unit) ? std::string("a fraction (-)") : unit) +
                         " (it converts %, kN, GPa, kPa, Pa, N/mm^2, um, cm, m, ms, min): give the column in " +
                         (dimensionless(unit) ? std::string("-") : unit));
  }
  if (f != 1.0)
    for (double& v : values) v *= f;
  own = unit;
}

}  // namespace spifit::inverse
