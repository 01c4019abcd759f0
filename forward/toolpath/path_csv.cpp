#include "forward/toolpath/path_csv.hpp"

#include "forward/io/text_file.hpp"

#include "forward/io/input_error.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace spifit::toolpath {

namespace {

using io::InputError;

enum Column { kX, kY, kZ, kFeed, kNumColumns };
constexpr std::array<const char*, kNumColumns> kNames{"x", "y", "z", "feed"};
constexpr std::array<const char*, kNumColumns> kUnits{"mm", "mm", "mm", "mm/s"};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Splits at every comma, keeping empty cells (also a trailing one).
std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  for (char c : line) {
    if (c == ',') cells.emplace_back();
    else cells.back() += c;
  }
  for (auto& c : cells) c = io::trim(c);
  return cells;
}

// A finite decimal number filling the whole cell ('+' sign and exponent allowed).
std::optional<double> parse_number(const std::string& s) {
  const std::size_t i = (!s.empty() && s[0] == '+') ? 1 : 0;  // from_chars rejects '+'
  if (i == s.size()) return std::nullopt;
  double v = 0.0;
  const auto r = std::from_chars(s.data() + i, s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}


struct Reader {
  const std::string& file;
  int line = 0;  // 1-based number of the line being read

  [[noreturn]] void fail(const std::string& value, const std::string& message) const {
    throw InputError(file, "line " + std::to_string(line), io::one_line(value, 80), message);
  }
};

// Column index of x, y, z, feed in the header (-1: feed absent).
std::array<int, kNumColumns> parse_header(const Reader& r, const std::string& text,
                                          std::size_t& num_cells) {
  std::array<int, kNumColumns> index{-1, -1, -1, -1};
  const auto cells = split_cells(text);
  num_cells = cells.size();
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const std::string& cell = cells[k];
    std::string name = cell, unit;
    if (const auto open = cell.find('['); open != std::string::npos) {
      if (cell.back() != ']') r.fail(cell, "unit must be written as 'name [unit]'");
      name = io::trim(cell.substr(0, open));
      unit = io::trim(cell.substr(open + 1, cell.size() - open - 2));
    }
    name = lower(name);
    const auto it = std::find(kNames.begin(), kNames.end(), name);
    if (it == kNames.end())
      r.fail(cell, "unknown column (the header is x, y, z and optionally feed)");
    const auto c = static_cast<std::size_t>(it - kNames.begin());
    if (index[c] >= 0) r.fail(cell, "column given twice");
    if (!unit.empty() && lower(unit) != kUnits[c])
      r.fail(cell, std::string("unsupported unit, expected [") + kUnits[c] + "] (no conversion)");
    index[c] = static_cast<int>(k);
  }
  for (std::size_t c = kX; c <= kZ; ++c)
    if (index[c] < 0) r.fail(text, std::string("missing column '") + kNames[c] + "'");
  return index;
}

}  // namespace

ToolPath read_path_csv(const std::string& file, double default_feed) {
  if (!std::isfinite(default_feed) || default_feed < 0.0)
    throw std::invalid_argument("CSV tool path default feed must be >= 0");
  std::string text = io::read_text_file(file);
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // UTF-8 byte order mark

  Reader r{file};
  std::optional<std::array<int, kNumColumns>> index;
  std::size_t num_cells = 0;
  std::string header;
  std::vector<Waypoint> points;
  std::istringstream in(text);
  std::string raw;
  while (std::getline(in, raw)) {
    ++r.line;
    const std::string row = io::trim(raw);
    if (row.empty() || row[0] == '#') continue;
    if (!index) {
      index = parse_header(r, row, num_cells);
      header = row;
      continue;
    }
    const auto cells = split_cells(row);
    const int feed_col = (*index)[kFeed];
    // A row may leave out the feed when it is the last column.
    const bool feed_left_out =
        feed_col >= 0 && static_cast<std::size_t>(feed_col) + 1 == num_cells && cells.size() + 1 == num_cells;
    if (cells.size() != num_cells && !feed_left_out)
      r.fail(row, "expected " + std::to_string(num_cells) + " values (header: " +
                      io::one_line(header, 80) + "), found " + std::to_string(cells.size()));
    Waypoint w;
    w.feed = default_feed;
    w.source_line = r.line;
    for (std::size_t c = 0; c < kNumColumns; ++c) {
      const int k = (*index)[c];
      if (k < 0 || static_cast<std::size_t>(k) >= cells.size()) continue;
      const std::string& cell = cells[static_cast<std::size_t>(k)];
      if (c == kFeed && cell.empty()) continue;  // empty feed: default
      const auto v = parse_number(cell);
      if (!v) r.fail(cell.empty() ? row : cell, std::string("not a number in column '") + kNames[c] + "'");
      if (c == kFeed) {
        if (*v < 0.0) r.fail(cell, "feed must be >= 0 (0 = rapid)");
        w.feed = *v;
      } else {
        w.position[static_cast<Eigen::Index>(c)] = *v;
      }
    }
    points.push_back(w);
  }
  r.line = std::max(1, r.line);  // errors about the whole file name its last line
  if (!index) r.fail("", "no header line (expected columns x, y, z and optionally feed)");
  if (points.size() < 2)
    r.fail("", "a tool path needs at least 2 points, found " + std::to_string(points.size()));
  return ToolPath(std::move(points));
}

}  // namespace spifit::toolpath
