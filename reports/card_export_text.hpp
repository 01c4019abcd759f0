#pragma once
// Deck text shared by the card exporters (card_export_abaqus.cpp, card_export_lsdyna.cpp,
// card_export_calculix.cpp): numbers, comment headers and the notes every deck carries.
// Internal to reports/.
#include "reports/card_export.hpp"

#include <sstream>
#include <string>
#include <vector>

namespace spifit::reports::deck {

// Shortest round-trip text of v (format_real without a width).
std::string num(double v);
// v with prec decimals (iostream fixed).
std::string fixed(double v, int prec);
// printf "%.*g".
std::string sci(double v, int prec);

// The comment block heading a deck: what, which card, units, then the numbered notes, each
// wrapped to `width` characters after `prefix` ("** " or "$ ").
void write_header(std::ostringstream& os, const std::string& prefix, const std::string& code, const material::MaterialCard& card,
                  const std::vector<std::string>& notes, std::size_t width);
// Appends notes to *out unless out is null.
void append(std::vector<std::string>* out, const std::vector<std::string>& notes);

// Notes shared by every exporter: the hardening table (table_what: where it goes; extrapolation:
// what the code does beyond it), the RD normalisation, Cauchy vs Kirchhoff stress.
std::vector<std::string> common_notes(const material::MaterialCard& card, const ExportedLaw& law, const ExportOptions& o,
                                      const std::string& table_what, const std::string& extrapolation);

// F = G = H and N = L = M = 3F: a scaled von Mises criterion, for which the Armstrong-Frederick
// back-stress moves along sigma - X and the Ziegler form reproduces it exactly.
bool proportional_to_von_mises(const material::Hill48& h);
// All Abaqus *POTENTIAL ratios are 1 (von Mises).
bool all_ratios_one(const material::AbaqusPotential& r);

}  // namespace spifit::reports::deck
