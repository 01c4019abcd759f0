#pragma once
// Small FE scene files for tests that run a scene several times (resume, sweeps): a line test
// on a 40 mm half sheet (72 elements, about 100 increments, a second or two).
#include <filesystem>
#include <fstream>
#include <string>

namespace spifit::test {

// The line test A -> B -> C -> D -> E shrunk: 3 mm deep, 16 mm along x, 5 mm deep, back; sections
// at C and E; `extra` is appended (e.g. an [output] table).
inline std::filesystem::path write_tiny_line(const std::filesystem::path& file, const std::string& output = "") {
  std::ofstream(file) << "[scene]\nkind = \"line\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                      << "[sheet]\nlength = 40.0\nthickness = 1.2\nelements = 12\n[tool]\nradius = 5.0\nfeed = 10.0\n"
                      << "[[path]]\nname = \"A\"\nx = -8.0\ny = 0.0\nz = 0.0\n[[path]]\nname = \"B\"\nx = -8.0\ny = 0.0\nz = -3.0\n"
                      << "[[path]]\nname = \"C\"\nx = 8.0\ny = 0.0\nz = -3.0\n[[path]]\nname = \"D\"\nx = 8.0\ny = 0.0\nz = -5.0\n"
                      << "[[path]]\nname = \"E\"\nx = -8.0\ny = 0.0\nz = -5.0\n"
                      << "[output]\nsections = [\"C\", \"E\"]\n" << output;
  return file;
}

}  // namespace spifit::test
