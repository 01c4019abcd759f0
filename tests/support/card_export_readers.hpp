#pragma once
// Readers for the decks written by reports/card_export.hpp: they parse the numbers back for the
// round-trip tests. Abaqus and CalculiX share the keyword syntax
// (*KEYWORD, PARAM=VALUE lines, comma-separated data lines, ** comments); LS-DYNA decks are
// read in fixed 10- or 20-character fields (long format, *KEYWORD LONG=Y) or comma-separated.
// Malformed input throws std::runtime_error naming the line.
#include "forward/material/hill48.hpp"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace spifit::test {

struct InpKeyword {
  std::string name;  // upper case, single blanks: "PLASTIC", "CYCLIC HARDENING"
  // Upper-case keys with blanks removed ("DATA TYPE" -> "DATATYPE"); values trimmed, case kept.
  std::map<std::string, std::string> parameters;
  std::vector<std::vector<double>> rows;  // data lines
  int line = 0;                           // 1-based line of the keyword
};

std::vector<InpKeyword> parse_inp_keywords(const std::string& deck);

struct InpMaterial {
  std::string name;
  double E = 0.0, nu = 0.0;
  std::optional<double> density;
  std::optional<material::AbaqusPotential> potential;
  std::string hardening = "ISOTROPIC";  // *PLASTIC HARDENING=
  std::string data_type;                // *PLASTIC DATATYPE= ("" = tabular)
  std::vector<std::array<double, 2>> plastic;  // (stress, plastic strain) rows when tabular
  std::vector<double> plastic_parameters;      // DATATYPE=PARAMETERS: sigma_0, C1, gamma1
  std::vector<std::array<double, 2>> cyclic_hardening;  // (stress, plastic strain)
};

// The first *MATERIAL block of an Abaqus or CalculiX deck (its options up to the next
// non-material keyword).
InpMaterial read_inp_material(const std::string& deck);

struct LsDynaMaterial {
  std::string keyword;  // "MAT_HILL_3R", "MAT_BARLAT_YLD2000" or "MAT_ELASTIC" (without _TITLE)
  std::string title;
  int mid = 0;
  double ro = 0.0, e = 0.0, pr = 0.0;
  double hr = 0.0, p1 = 0.0, p2 = 0.0;           // MAT_122
  double r00 = 0.0, r45 = 0.0, r90 = 0.0, e0 = 0.0, aopt = 0.0;
  int lcid = 0;
  std::array<double, 3> a{}, v{}, d{};
  double beta = 0.0;
  double fit = 0.0, iter = 0.0, hard = 0.0, exponent = 0.0;  // MAT_133 (HARD < 0: -LCID)
  std::array<double, 8> alpha{};                              // MAT_133 ALPHA1..ALPHA8
  // *DEFINE_CURVE with id lcid: (abscissa, ordinate) scaled by SFA/SFO and offset by OFFA/OFFO.
  std::vector<std::array<double, 2>> curve;
};

LsDynaMaterial read_lsdyna_material(const std::string& deck);

}  // namespace spifit::test
