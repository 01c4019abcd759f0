#include "reports/export_calculix_check.hpp"

#include "reports/card_export.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace spifit::reports {

std::string calculix_tension_deck(const std::string& material_block, const std::string& material_name,
                                  const CalculixTensionOptions& o) {
  if (o.log_strain_path.empty() || o.increments < 1 || !(o.length > 0.0)) {
    throw std::invalid_argument("calculix_tension_deck: empty path, increments < 1 or length <= 0");
  }
  const double L = o.length;
  std::ostringstream os;
  os << "** spifit " SPIFIT_VERSION ": one C3D8 element in uniaxial tension (NLGEOM), check of an exported card\n";
  os << "*HEADING\nspifit one-element uniaxial check of " << material_name << "\n";
  os << "*NODE, NSET=NALL\n";
  const double xyz[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int i = 0; i < 8; ++i) {
    os << i + 1 << ", " << format_real(xyz[i][0] * L) << ", " << format_real(xyz[i][1] * L) << ", "
       << format_real(xyz[i][2] * L) << "\n";
  }
  os << "*ELEMENT, TYPE=C3D8, ELSET=EALL\n1, 1, 2, 3, 4, 5, 6, 7, 8\n";
  os << "*NSET, NSET=XMIN\n1, 4, 5, 8\n*NSET, NSET=XMAX\n2, 3, 6, 7\n";
  os << "*NSET, NSET=YMIN\n1, 2, 5, 6\n*NSET, NSET=ZMIN\n1, 2, 3, 4\n";
  os << material_block;
  if (!material_block.empty() && material_block.back() != '\n') os << "\n";
  os << "*SOLID SECTION, ELSET=EALL, MATERIAL=" << material_name << "\n";
  os << "*BOUNDARY\nXMIN, 1, 1, 0\nYMIN, 2, 2, 0\nZMIN, 3, 3, 0\n";
  const double dt = 1.0 / o.increments;
  for (double eps : o.log_strain_path) {
    os << "*STEP, NLGEOM, INC=" << 10 * o.increments << "\n";
    os << "*STATIC, DIRECT\n" << format_real(dt, 20) << ", 1.0\n";
    os << "*BOUNDARY\nXMAX, 1, 1, " << format_real(L * std::expm1(eps), 20) << "\n";
    os << "*NODE PRINT, NSET=XMAX\nU\n";
    os << "*EL PRINT, ELSET=EALL\nS, E, PEEQ\n";
    os << "*END STEP\n";
  }
  return os.str();
}

namespace {

bool parse_numbers(const std::string& line, std::vector<double>* out) {
  std::istringstream is(line);
  out->clear();
  std::string tok;
  while (is >> tok) {
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0') return false;
    out->push_back(v);
  }
  return !out->empty();
}

}  // namespace

std::vector<CalculixTensionPoint> read_calculix_tension_dat(const std::string& dat, double length) {
  enum class Block { none, u, s, e, pe };
  std::map<double, CalculixTensionPoint> points;
  std::map<double, std::map<Block, int>> counts;
  Block block = Block::none;
  double time = 0.0;
  std::istringstream is(dat);
  std::string line;
  std::vector<double> v;
  int ln = 0;
  while (std::getline(is, line)) {
    ++ln;
    const auto for_set = line.find("for set");
    if (for_set != std::string::npos) {
      const auto t = line.find("time", for_set);
      if (t == std::string::npos) throw std::runtime_error("ccx .dat line " + std::to_string(ln) + ": no time");
      time = std::strtod(line.c_str() + t + 4, nullptr);
      if (line.find("displacements") != std::string::npos) block = Block::u;
      else if (line.find("stresses") != std::string::npos) block = Block::s;
      else if (line.find("strains") != std::string::npos && line.find("plastic") == std::string::npos) block = Block::e;
      else if (line.find("equivalent plastic strain") != std::string::npos) block = Block::pe;
      else block = Block::none;
      points[time].time = time;
      continue;
    }
    if (block == Block::none || !parse_numbers(line, &v)) continue;
    auto& p = points[time];
    auto& n = counts[time][block];
    auto mean = [&](double* acc, double x) { *acc = (*acc * n + x) / (n + 1); };
    if (block == Block::u && v.size() >= 4) mean(&p.u, v[1]);
    else if (block == Block::s && v.size() >= 8) mean(&p.stress, v[2]);
    else if (block == Block::e && v.size() >= 8) mean(&p.lagrange_strain, v[2]);
    else if (block == Block::pe && v.size() >= 3) mean(&p.peeq, v[2]);
    else throw std::runtime_error("ccx .dat line " + std::to_string(ln) + ": unexpected data '" + line + "'");
    ++n;
  }
  std::vector<CalculixTensionPoint> out;
  for (auto& [t, p] : points) {
    const auto& c = counts[t];
    if (!c.count(Block::u) || !c.count(Block::s)) {
      throw std::runtime_error("ccx .dat: time " + std::to_string(t) + " lacks displacements or stresses");
    }
    p.log_strain = std::log1p(p.u / length);
    out.push_back(p);
  }
  if (out.empty()) throw std::runtime_error("ccx .dat: no results");
  return out;
}

std::string find_calculix() {
  if (const char* env = std::getenv("SPIFIT_CCX"); env && *env) return env;
  const char* path = std::getenv("PATH");
  if (!path) return "";
  std::istringstream is(path);
  std::string dir;
  while (std::getline(is, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path p = std::filesystem::path(dir) / "ccx";
    if (::access(p.c_str(), X_OK) == 0) return p.string();
  }
  return "";
}

}  // namespace spifit::reports
