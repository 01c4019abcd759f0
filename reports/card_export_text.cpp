#include "reports/card_export_text.hpp"

#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/yield/yield_functions.hpp"

#include <cmath>
#include <cstdio>

namespace spifit::reports::deck {

using material::MaterialCard;

namespace {

// Splits a note into comment lines of at most `width` characters after the prefix.
void write_comment(std::ostringstream& os, const std::string& prefix, const std::string& text, std::size_t width,
                   const std::string& indent = "") {
  std::istringstream words(text);
  std::string word, line;
  bool first = true;
  auto flush = [&] {
    os << prefix << (first ? "" : indent) << line << "\n";
    first = false;
    line.clear();
  };
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) flush();
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty() || first) flush();
}

}  // namespace

bool proportional_to_von_mises(const material::Hill48& h) {
  const double c = h.F, tol = 1e-12 * std::abs(c);
  return std::abs(h.G - c) <= tol && std::abs(h.H - c) <= tol && std::abs(h.N - 3 * c) <= 3 * tol &&
         std::abs(h.L - 3 * c) <= 3 * tol && std::abs(h.M - 3 * c) <= 3 * tol;
}

bool all_ratios_one(const material::AbaqusPotential& r) {
  for (double v : {r.R11, r.R22, r.R33, r.R12, r.R13, r.R23}) {
    if (std::abs(v - 1.0) > 1e-12) return false;
  }
  return true;
}

std::string num(double v) { return format_real(v); }

void write_header(std::ostringstream& os, const std::string& prefix, const std::string& code, const MaterialCard& card,
                  const std::vector<std::string>& notes, std::size_t width) {
  write_comment(os, prefix, "spifit " SPIFIT_VERSION " export of material card \"" + card.name + "\" for " + code, width);
  if (!card.description.empty()) write_comment(os, prefix, "description: " + card.description, width, "  ");
  if (!card.source.empty()) write_comment(os, prefix, "source: " + card.source, width, "  ");
  if (!card.file.empty()) write_comment(os, prefix, "card file: " + card.file, width, "  ");
  if (card.fitted) {
    const material::FitProvenance& f = *card.fitted;
    if (!f.usable) write_comment(os, prefix, "NOT USABLE: the fit that wrote this card did not give a usable result (its fit.json says why)", width, "  ");
    write_comment(os, prefix, "fitted by spifit " + f.spifit_version + " on " + f.date + " from fit file " + f.fit_file + ", start card " + f.start_card,
                  width, "  ");
    for (const auto& d : f.data) write_comment(os, prefix, "data: " + d, width, "  ");
  }
  write_comment(os, prefix, "units: mm, N, s, t (tonne); stress MPa; density t/mm^3", width);
  write_comment(os, prefix, "conventions and approximations (docs/reference/outputs.md):", width);
  for (std::size_t i = 0; i < notes.size(); ++i) {
    write_comment(os, prefix, std::to_string(i + 1) + ". " + notes[i], width, "   ");
  }
}

void append(std::vector<std::string>* out, const std::vector<std::string>& notes) {
  if (out) out->insert(out->end(), notes.begin(), notes.end());
}

std::string fixed(double v, int prec) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(prec);
  os << v;
  return os.str();
}

std::string sci(double v, int prec) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", prec, v);
  return buf;
}

std::vector<std::string> common_notes(const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o,
                                      const std::string& table_what, const std::string& extrapolation) {
  std::vector<std::string> n;
  const auto& p = card.params;
  if (!p.plastic) {
    n.push_back("elastic-only card (no hardening table): no plasticity is written.");
    return n;
  }
  const material::HardeningLawInfo& hardening = material::hardening_law(p.hardening.law);
  n.push_back(hardening.title + " hardening " + hardening.formula + " is tabulated (" + table_what + ") at " +
              std::to_string(law.strain.size()) + " points: ebar = 0, then a geometric grid from " +
              sci(law.strain[1], 3) + " to " + sci(o.max_plastic_strain, 3) +
              " (equivalent plastic strain); the FE code interpolates linearly: largest relative deviation from the "
              "analytic curve " + sci(law.interpolation_error, 2) + ". Beyond ebar = " + sci(o.max_plastic_strain, 3) +
              " " + extrapolation + ".");
  if (p.yield.active()) {
    n.push_back(material::yield_function_title(p.yield.law) + ": the deck is normalised to the RD tensile yield stress "
                "(exact, no approximation): every alpha is divided by h = sigma_eq of a unit RD tension = " + num(law.h) +
                " (sigma_eq is homogeneous of degree one in the alphas), the curve is sigma_F(ebar/h)/h and ebar = h p.");
  } else if (std::abs(law.h - 1.0) > 1e-12) {
    n.push_back("G + H = " + num(card.params.G + card.params.H) +
                " != 2: the deck is normalised to the RD tensile yield stress (exact, no approximation): yield-surface "
                "size sigma_0 = sigma_F(ebar/h)/h and ebar = h p with h = sqrt((G+H)/2) = " + num(law.h) +
                "; spifit's p = ebar/h.");
  }
  n.push_back("tables are true (Cauchy) stress [MPa] vs logarithmic equivalent plastic strain; spifit's law is written "
              "in Kirchhoff stress (tau = J sigma, yield on tau): the two differ by the elastic volume change, J - 1 = "
              "(1 - 2 nu) tr(sigma)/E (6e-4 at 150 MPa uniaxial for AA3003-O, docs/design/numerics-material.md).");
  return n;
}

}  // namespace spifit::reports::deck
