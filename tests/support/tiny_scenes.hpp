#pragma once
// Small FE scene files for tests that run a scene several times (resume, sweeps, observables):
// a line test on a 40 mm half sheet and a one- or few-contour 45 deg cone on a 90 deg pie.
#include <charconv>
#include <filesystem>
#include <fstream>
#include <string>

namespace spifit::test {

// The line test A -> B -> C -> D -> E shrunk: 3 mm deep, 16 mm along x, 5 mm deep, back; sections
// at C and E, 72 elements, about 100 increments, a second or two; `output` is appended to its
// [output] table (e.g. "checkpoint_increments = 5\n").
inline std::filesystem::path write_tiny_line(const std::filesystem::path& file, const std::string& output = "") {
  std::ofstream(file) << "[scene]\nkind = \"line\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                      << "[sheet]\nlength = 40.0\nthickness = 1.2\nelements = 12\n[tool]\nradius = 5.0\nfeed = 10.0\n"
                      << "[[path]]\nname = \"A\"\nx = -8.0\ny = 0.0\nz = 0.0\n[[path]]\nname = \"B\"\nx = -8.0\ny = 0.0\nz = -3.0\n"
                      << "[[path]]\nname = \"C\"\nx = 8.0\ny = 0.0\nz = -3.0\n[[path]]\nname = \"D\"\nx = 8.0\ny = 0.0\nz = -5.0\n"
                      << "[[path]]\nname = \"E\"\nx = -8.0\ny = 0.0\nz = -5.0\n"
                      << "[output]\nsections = [\"C\", \"E\"]\n" << output;
  return file;
}

// A TOML float: the shortest text that reads back as v, with a decimal point.
inline std::string toml_float(double v) {
  char buf[64];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  std::string s(buf, end);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

// The tiny cone: 45 deg wall, 0.5 mm stepdown, 1 mm sheet with 3 thickness points (shells and
// solid-shells), on a coarse 90 deg pie, card C.3 + C.4.
struct TinyCone {
  int contours = 1;
  double top_radius = 20.0;           // 128 elements with elements_per_45deg = 8
  int elements_per_45deg = 8;
  double travel_per_increment = 0.5;  // mm
  std::string element = "shell";      // [sheet] element; a brick sheet has `layers` instead of thickness points
  int layers = 0;                     // > 0: [sheet] layers
};
// Its smaller cousin: top radius 12 mm, 6 elements per 45 deg (72 elements, about a second a contour).
inline TinyCone small_tiny_cone(int contours = 1) { return {contours, 12.0, 6, 0.5}; }

// Writes the tiny cone to `file`. Its last table is [solver], so `extra` may begin with solver
// keys (e.g. "move_increments = 1\n") before tables of its own.
inline std::filesystem::path write_tiny_cone(const std::filesystem::path& file, const std::string& extra = "", const TinyCone& c = {}) {
  std::ofstream(file) << "[scene]\nkind = \"cone\"\nmaterial = \"" << SPIFIT_SOURCE_DIR << "/materials/aa3003o_c3c4.toml\"\n"
                      << "[cone]\nwall_angle = 45.0\nstepdown = 0.5\ncontours = " << c.contours << "\ntop_radius = " << toml_float(c.top_radius)
                      << "\npie_angle = 90.0\n"
                      << "[sheet]\nthickness = 1.0\nelements_per_45deg = " << c.elements_per_45deg << "\n"
                      << (c.element == "brick" ? "" : "thickness_points = 3\n")
                      << (c.element == "shell" ? "" : "element = \"" + c.element + "\"\n")
                      << (c.layers > 0 ? "layers = " + std::to_string(c.layers) + "\n" : "")
                      << "[solver]\ntravel_per_increment = " << toml_float(c.travel_per_increment) << "\n"
                      << extra;
  return file;
}

}  // namespace spifit::test
