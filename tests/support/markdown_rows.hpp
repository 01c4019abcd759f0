#pragma once
// Cells of a row of a Markdown table as the reports write them (markdown_writer.hpp).
#include <sstream>
#include <string>
#include <vector>

namespace spifit::test {

// Cells of the first Markdown table row that starts with "| NAME |" (escapes removed, blanks
// trimmed; the cell NAME first); empty when there is none.
inline std::vector<std::string> md_row(const std::string& md, const std::string& name) {
  std::istringstream in(md);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| " + name + " |", 0) != 0) continue;
    std::vector<std::string> cells;
    std::string cell;
    for (std::size_t i = 1; i < line.size(); ++i) {
      if (line[i] == '\\' && i + 1 < line.size()) {
        cell += line[++i];
      } else if (line[i] == '|') {
        const auto a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
        cells.push_back(a == std::string::npos ? std::string() : cell.substr(a, b - a + 1));
        cell.clear();
      } else {
        cell += line[i];
      }
    }
    return cells;
  }
  return {};
}

// The text of a Markdown document from the heading line "HEADING" (e.g. "## Forward runs") to
// the next heading of that level or higher; empty when there is no such heading.
inline std::string md_section(const std::string& md, const std::string& heading) {
  const auto a = md.find("\n" + heading + "\n");
  if (a == std::string::npos) return {};
  const std::string level = heading.substr(0, heading.find(' ') + 1);  // "## "
  std::size_t b = a + 1;
  while ((b = md.find("\n#", b + 1)) != std::string::npos) {
    const auto hashes = md.find_first_not_of('#', b + 1) - (b + 1);
    if (hashes <= level.size() - 1) break;
  }
  return md.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1);
}

}  // namespace spifit::test
