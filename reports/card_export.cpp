#include "reports/card_export.hpp"

#include "forward/material/swift_hardening.hpp"
#include "forward/scenes/material_point/material_point_run.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace spifit::reports {

using material::KinematicLaw;
using material::MaterialCard;

std::string to_string(ExportFormat f) {
  switch (f) {
    case ExportFormat::lsdyna: return "lsdyna";
    case ExportFormat::calculix: return "calculix";
    default: return "abaqus";
  }
}

bool export_format_from_string(const std::string& s, ExportFormat* f) {
  if (s == "abaqus") *f = ExportFormat::abaqus;
  else if (s == "lsdyna" || s == "ls-dyna") *f = ExportFormat::lsdyna;
  else if (s == "calculix" || s == "ccx") *f = ExportFormat::calculix;
  else return false;
  return true;
}

std::string default_extension(ExportFormat f) { return f == ExportFormat::lsdyna ? ".k" : ".inp"; }

bool ExportOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (!(first_plastic_strain > 0.0)) return fail("first_plastic_strain must be > 0");
  if (!(max_plastic_strain > first_plastic_strain)) return fail("max_plastic_strain must be > first_plastic_strain");
  if (table_points < 2 || table_points > 199) return fail("table_points must lie in [2, 199] (CalculiX keeps 200 points per curve)");
  if (lsdyna_material_id < 1 || lsdyna_curve_id < 1) return fail("LS-DYNA ids must be >= 1");
  return true;
}

std::string format_real(double v, int max_width) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, res.ptr);
  if (max_width <= 0 || static_cast<int>(s.size()) <= max_width) return s;
  for (int prec = 17; prec >= 1; --prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, v);
    if (static_cast<int>(std::strlen(buf)) <= max_width) return buf;
  }
  throw std::invalid_argument("format_real: " + s + " does not fit in " + std::to_string(max_width) + " characters");
}

std::string deck_material_name(const MaterialCard& card) {
  std::string n = card.name.empty() ? std::string("spifit_material") : card.name;
  for (char& ch : n) {
    const bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_';
    if (!ok) ch = '_';
  }
  if (!((n[0] >= 'a' && n[0] <= 'z') || (n[0] >= 'A' && n[0] <= 'Z'))) n = "M_" + n;
  if (n.size() > 80) n.resize(80);
  return n;
}

double rd_back_stress(double C, double gamma, double ebar) {
  const double x = gamma * ebar;
  if (x == 0.0) return C * ebar;
  return C * ebar * (-std::expm1(-x) / x);  // (C/gamma)(1 - e^-x), accurate for small x
}

namespace {

// F = G = H and N = L = M = 3F: a scaled von Mises criterion, for which the Armstrong-Frederick
// back-stress moves along sigma - X and the Ziegler form reproduces it exactly.
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

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double xv) {
  if (xv <= x.front()) return y.front();
  if (xv >= x.back()) return y.back();
  const auto it = std::upper_bound(x.begin(), x.end(), xv);
  const std::size_t i = static_cast<std::size_t>(it - x.begin());
  const double t = (xv - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

std::string num(double v) { return format_real(v); }

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

void write_header(std::ostringstream& os, const std::string& prefix, const std::string& code, const MaterialCard& card,
                  const std::vector<std::string>& notes, std::size_t width) {
  write_comment(os, prefix, "spifit " SPIFIT_VERSION " export of material card \"" + card.name + "\" for " + code, width);
  if (!card.description.empty()) write_comment(os, prefix, "description: " + card.description, width, "  ");
  if (!card.source.empty()) write_comment(os, prefix, "source: " + card.source, width, "  ");
  if (!card.file.empty()) write_comment(os, prefix, "card file: " + card.file, width, "  ");
  write_comment(os, prefix, "units: mm, N, s, t (tonne); stress MPa; density t/mm^3", width);
  write_comment(os, prefix, "conventions and approximations (docs/exports.md):", width);
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

// Notes shared by every exporter.
std::vector<std::string> common_notes(const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o,
                                      const std::string& table_what, const std::string& extrapolation) {
  std::vector<std::string> n;
  const auto& p = card.params;
  if (!p.plastic) {
    n.push_back("elastic-only card (no [swift] table): no plasticity is written.");
    return n;
  }
  n.push_back("Swift hardening sigma_F = K (eps0 + p)^n is tabulated (" + table_what + ") at " +
              std::to_string(law.strain.size()) + " points: ebar = 0, then a geometric grid from " +
              sci(law.strain[1], 3) + " to " + sci(o.max_plastic_strain, 3) +
              " (equivalent plastic strain); the FE code interpolates linearly: largest relative deviation from the "
              "analytic curve " + sci(law.interpolation_error, 2) + ". Beyond ebar = " + sci(o.max_plastic_strain, 3) +
              " " + extrapolation + ".");
  if (std::abs(law.h - 1.0) > 1e-12) {
    n.push_back("G + H = " + num(card.params.G + card.params.H) +
                " != 2: the deck is normalised to the RD tensile yield stress (exact, no approximation): yield-surface "
                "size sigma_0 = sigma_F(ebar/h)/h and ebar = h p with h = sqrt((G+H)/2) = " + num(law.h) +
                "; spifit's p = ebar/h.");
  }
  n.push_back("tables are true (Cauchy) stress [MPa] vs logarithmic equivalent plastic strain; spifit's law is written "
              "in Kirchhoff stress (tau = J sigma, yield on tau): the two differ by the elastic volume change, J - 1 = "
              "(1 - 2 nu) tr(sigma)/E (6e-4 at 150 MPa uniaxial for AA3003-O, docs/material-point-scenes.md).");
  return n;
}

// Largest stress differences between the card and the exported law (spifit's integrator for
// both): tension to 0.2 and back to 0.1 at 0, 45 and 90 degrees, and simple shear along RD to
// gamma = 0.2 and back to -0.1.
struct Deviation {
  double tension = 0.0, tension_peak = 0.0, tension_angle = 0.0;
  double shear = 0.0, shear_peak = 0.0;
  bool ok = true;
};

Deviation measure_deviation(const MaterialCard& card, const MaterialCard& exported) {
  Deviation d;
  auto run = [&](scene::MaterialPointKind kind, double angle, std::vector<double> path, double* worst, double* peak,
                 double* worst_angle) {
    scene::MaterialPointSetup s;
    s.kind = kind;
    s.angle_deg = angle;
    s.strain_path = std::move(path);
    s.increments = 150;
    s.want_r_value = false;
    s.want_offset_yield = false;
    const auto a = scene::run_material_point(card.params, s);
    const auto b = scene::run_material_point(exported.params, s);
    if (!a.ok || !b.ok || a.curve.size() != b.curve.size()) {
      d.ok = false;
      return;
    }
    for (std::size_t i = 0; i < a.curve.size(); ++i) {
      *peak = std::max(*peak, std::abs(a.curve[i].stress));
      const double e = std::abs(a.curve[i].stress - b.curve[i].stress);
      if (e > *worst) {
        *worst = e;
        if (worst_angle) *worst_angle = angle;
      }
    }
  };
  for (double angle : {0.0, 45.0, 90.0}) {
    run(scene::MaterialPointKind::tensile, angle, {0.2, 0.1}, &d.tension, &d.tension_peak, &d.tension_angle);
  }
  run(scene::MaterialPointKind::bauschinger, 0.0, {0.2, -0.1}, &d.shear, &d.shear_peak, nullptr);
  return d;
}

std::string kinematic_note(const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o) {
  const auto& p = card.params;
  std::string s;
  if (law.kinematic == KinematicLaw::ziegler) {
    s = "Ziegler kinematic hardening (eq. 3.9) is Abaqus's nonlinear kinematic law: C = CA/h^2 = " + num(law.C) +
        " MPa, gamma = GA/h = " + num(law.gamma) + " (CA = " + num(p.CA) + ", GA = " + num(p.GA) + ", h = " + num(law.h) +
        "): exact.";
  } else if (law.kinematic_exact) {
    s = "Armstrong-Frederick kinematic hardening (eq. 3.8, tensor components) with von Mises: gamma = CX/h = " +
        num(law.gamma) + ", C = 1.5 CX Xsat/h = " + num(law.C) + " MPa (CX = " + num(p.CX) + ", Xsat = " + num(p.Xsat) +
        "): exact for von Mises.";
  } else {
    s = "APPROXIMATION: Armstrong-Frederick (eq. 3.8) with Hill moves the back-stress along the Hill normal; no Abaqus "
        "(C, gamma) reproduces it. Exported the nearest Ziegler-form pair, matching the initial rate and the saturation "
        "of the RD tensile back-stress: gamma = CX/h = " + num(law.gamma) + ", C = CX Xsat k/h^2 = " + num(law.C) +
        " MPa, k = ((G+H)^2 + G^2 + H^2)/(2(G+H)) = " +
        num(((p.G + p.H) * (p.G + p.H) + p.G * p.G + p.H * p.H) / (2 * (p.G + p.H))) + " (1.5 for von Mises).";
    if (o.measure_approximations) {
      const Deviation d = measure_deviation(card, exported_equivalent_card(card));
      if (d.ok) {
        s += " Measured with spifit, card vs exported law: tension to 0.2 and back to 0.1 at 0/45/90 deg, largest "
             "stress difference " + fixed(d.tension, 1) + " MPa (" + fixed(100.0 * d.tension / d.tension_peak, 1) +
             " % of " + fixed(d.tension_peak, 1) + " MPa, at " + fixed(d.tension_angle, 0) +
             " deg); simple shear along RD to 0.2 and back to -0.1, " + fixed(d.shear, 1) + " MPa (" +
             fixed(100.0 * d.shear / d.shear_peak, 1) + " % of " + fixed(d.shear_peak, 1) +
             " MPa). Where this matters, use a user material (VUMAT) with spifit's law.";
      }
    }
  }
  return s;
}

std::vector<std::string> abaqus_notes(const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o) {
  auto n = common_notes(card, law, o, law.kinematic == KinematicLaw::none ? "*PLASTIC" : "*CYCLIC HARDENING",
                        "Abaqus keeps the last yield stress (perfectly plastic)");
  if (!card.params.plastic) return n;
  if (!all_ratios_one(law.ratios)) {
    n.push_back("Hill 1948: spifit stores the thesis notation (eq. 3.5, factor 1/2, von Mises F = G = H = 1, N = L = M "
                "= 3, L on xz, M on yz); *POTENTIAL takes stress ratios R11 = 1, R22 = sqrt((G+H)/(F+H)), R33 = "
                "sqrt((G+H)/(F+G)), R12 = sqrt(1.5 (G+H)/N), R13 = sqrt(1.5 (G+H)/L) (thesis L = xz), R23 = sqrt(1.5 "
                "(G+H)/M) (thesis M = yz); for G + H = 2 these are sqrt(2/(F+H)), sqrt(2/(F+G)), sqrt(3/N), ...");
    n.push_back("the ratios refer to the local material axes: give the section an *ORIENTATION with 1 = RD, 2 = TD, "
                "3 = ND.");
  } else {
    n.push_back("von Mises card: no *POTENTIAL (all stress ratios are 1).");
  }
  if (law.kinematic != KinematicLaw::none) {
    n.push_back(kinematic_note(card, law, o));
    n.push_back("combined hardening: *PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS gives sigma_0(0), C, gamma; "
                "*CYCLIC HARDENING gives the isotropic size sigma_0(ebar) (Swift).");
    if (!all_ratios_one(law.ratios)) {
      n.push_back("Abaqus/Standard allows nonlinear isotropic/kinematic hardening with the Mises yield surface only: "
                  "Hill (*POTENTIAL) + this kinematic hardening runs in Abaqus/Explicit only.");
    }
  }
  return n;
}

}  // namespace

ExportedLaw exported_law(const MaterialCard& card, const ExportOptions& o) {
  std::string err;
  if (!o.IsValid(&err)) throw std::invalid_argument("ExportOptions: " + err);
  const auto& p = card.params;
  const material::Hill48 hill = card.hill();
  ExportedLaw law;
  const double gh = hill.G + hill.H;
  law.h = std::sqrt(0.5 * gh);
  law.ratios = {1.0,
                std::sqrt(gh / (hill.F + hill.H)),
                std::sqrt(gh / (hill.F + hill.G)),
                std::sqrt(1.5 * gh / hill.N),
                std::sqrt(1.5 * gh / hill.L),
                std::sqrt(1.5 * gh / hill.M)};
  law.lankford = material::lankford_from_hill(hill);
  law.plastic = p.plastic;
  law.kinematic = p.plastic ? p.kinematic : KinematicLaw::none;
  if (!p.plastic) return law;

  if (law.kinematic == KinematicLaw::ziegler) {
    law.C = p.CA / (law.h * law.h);
    law.gamma = p.GA / law.h;
  } else if (law.kinematic == KinematicLaw::armstrong_frederick) {
    const double k = (gh * gh + hill.G * hill.G + hill.H * hill.H) / (2.0 * gh);
    law.C = p.CX * p.Xsat * k / (law.h * law.h);
    law.gamma = p.CX / law.h;
    law.kinematic_exact = proportional_to_von_mises(hill);
  }

  const double h = law.h;
  auto size_at = [&](double e) { return material::swift_yield_stress(p, e / h) / h; };
  auto mono_at = [&](double e) { return size_at(e) + rd_back_stress(law.C, law.gamma, e); };
  const double e1 = std::min(o.first_plastic_strain, 0.1 * h * p.eps0);
  const int n = o.table_points;
  law.strain.push_back(0.0);
  for (int i = 0; i < n; ++i) {
    const double t = n == 1 ? 1.0 : static_cast<double>(i) / (n - 1);
    law.strain.push_back(i == n - 1 ? o.max_plastic_strain : e1 * std::pow(o.max_plastic_strain / e1, t));
  }
  for (double e : law.strain) {
    law.size.push_back(size_at(e));
    law.monotonic.push_back(mono_at(e));
  }
  // Linear-interpolation error, sampled inside every interval.
  for (std::size_t i = 1; i < law.strain.size(); ++i) {
    for (int k = 1; k < 16; ++k) {
      const double e = law.strain[i - 1] + (law.strain[i] - law.strain[i - 1]) * k / 16.0;
      law.interpolation_error = std::max(law.interpolation_error,
                                         std::abs(interpolate(law.strain, law.size, e) - size_at(e)) / size_at(e));
      law.interpolation_error = std::max(law.interpolation_error,
                                         std::abs(interpolate(law.strain, law.monotonic, e) - mono_at(e)) / mono_at(e));
    }
  }
  return law;
}

MaterialCard exported_equivalent_card(const MaterialCard& card) {
  const ExportedLaw law = exported_law(card);
  MaterialCard eq = card;
  eq.name = card.name + "_exported";
  material::Hill48 hill = card.hill();
  const double s = 1.0 / (law.h * law.h);
  hill.F *= s; hill.G *= s; hill.H *= s; hill.L *= s; hill.M *= s; hill.N *= s;
  eq.set_hill(hill);
  auto& p = eq.params;
  if (p.plastic) {
    p.K = card.params.K * std::pow(law.h, -(1.0 + card.params.n));
    p.eps0 = law.h * card.params.eps0;
    if (law.kinematic != KinematicLaw::none) {
      p.kinematic = KinematicLaw::ziegler;
      p.CA = law.C;
      p.GA = law.gamma;
      p.CX = 0.0;
      p.Xsat = 0.0;
    }
  }
  return eq;
}

std::string export_abaqus(const MaterialCard& card, std::vector<std::string>* notes_out, const ExportOptions& o) {
  const ExportedLaw law = exported_law(card, o);
  const auto notes = abaqus_notes(card, law, o);
  append(notes_out, notes);
  std::ostringstream os;
  write_header(os, "** ", "Abaqus (*MATERIAL block; Standard and Explicit)", card, notes, 96);
  os << "*MATERIAL, NAME=" << deck_material_name(card) << "\n";
  os << "*DENSITY\n" << num(card.density) << "\n";
  os << "*ELASTIC\n" << num(card.params.E) << ", " << num(card.params.nu) << "\n";
  if (law.plastic) {
    if (law.kinematic == KinematicLaw::none) {
      os << "** yield stress [MPa], equivalent plastic strain\n*PLASTIC\n";
      for (std::size_t i = 0; i < law.strain.size(); ++i) os << num(law.size[i]) << ", " << num(law.strain[i]) << "\n";
    } else {
      os << "** yield stress at zero plastic strain [MPa], C1 [MPa], gamma1\n";
      os << "*PLASTIC, HARDENING=COMBINED, DATATYPE=PARAMETERS\n";
      os << num(law.size.front()) << ", " << num(law.C) << ", " << num(law.gamma) << "\n";
      os << "** size of the elastic range [MPa], equivalent plastic strain\n*CYCLIC HARDENING\n";
      for (std::size_t i = 0; i < law.strain.size(); ++i) os << num(law.size[i]) << ", " << num(law.strain[i]) << "\n";
    }
    if (!all_ratios_one(law.ratios)) {
      const auto& r = law.ratios;
      os << "** R11, R22, R33, R12, R13, R23 (1 = RD, 2 = TD, 3 = ND)\n*POTENTIAL\n";
      os << num(r.R11) << ", " << num(r.R22) << ", " << num(r.R33) << ", " << num(r.R12) << ", " << num(r.R13) << ", "
         << num(r.R23) << "\n";
    }
  }
  return os.str();
}

namespace {

constexpr int kW = 20;  // LS-DYNA long-format field width

std::string field(double v) {
  std::string s = format_real(v, kW - 1);  // keep one blank between fields
  return std::string(static_cast<std::size_t>(kW) - s.size(), ' ') + s;
}
std::string field(int v) {
  std::string s = std::to_string(v);
  return std::string(static_cast<std::size_t>(kW) - s.size(), ' ') + s;
}
std::string blank() { return std::string(kW, ' '); }
std::string labels(std::initializer_list<const char*> names) {
  std::string s = "$#";
  bool first = true;
  for (const char* n : names) {
    std::string f(n);
    const std::size_t w = first ? kW - 2 : kW;
    if (f.size() >= w) f = f.substr(0, w - 1);
    s += std::string(w - f.size(), ' ') + f;
    first = false;
  }
  return s + "\n";
}

std::vector<std::string> lsdyna_notes(const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o) {
  const auto& p = card.params;
  auto n = common_notes(card, law, o, "*DEFINE_CURVE, effective plastic strain vs yield stress",
                        "LS-DYNA extrapolates the last segment of the curve");
  n.push_back("keyword file in long format (*KEYWORD LONG=Y, 20-character fields) so that every number keeps 14 "
              "significant digits; include it as a separate file.");
  if (!p.plastic) {
    n.push_back("*MAT_ELASTIC (MAT_001).");
    return n;
  }
  n.push_back("*MAT_HILL_3R (MAT_122): Hill 1948 for shell elements (plane stress), given by r-values r00 = H/G, r45 = "
              "(2N - F - G)/(2(F + G)), r90 = H/F (thesis eq. C.2) and the RD hardening curve: exact for the in-plane "
              "Hill coefficients; the card's out-of-plane L, M are not used.");
  n.push_back("material axes: AOPT = 2 with a = global x = RD and d = global y = TD (spifit's convention); change A/D "
              "(or AOPT) to match the mesh.");
  if (law.kinematic == KinematicLaw::none) {
    n.push_back("analytic alternative: HR = 2 (sigma = P1 (E0 + ebar)^P2) with P1 = K h^-(1+n) = " +
                num(p.K * std::pow(law.h, -(1.0 + p.n))) + ", P2 = n = " + num(p.n) + ", E0 = h eps0 = " +
                num(law.h * p.eps0) + " gives the same curve; the deck uses HR = 3 (load curve).");
  } else {
    const double xmax = law.gamma > 0 ? law.C / law.gamma : rd_back_stress(law.C, law.gamma, o.max_plastic_strain);
    n.push_back("APPROXIMATION: *MAT_122 has no kinematic hardening. The curve is the card's monotonic RD tension "
                "(isotropic size + RD back-stress (C/gamma)(1 - exp(-gamma ebar)), C = " + num(law.C) +
                " MPa, gamma = " + num(law.gamma) + "), i.e. isotropic hardening equivalent in monotonic RD tension" +
                (law.kinematic_exact ? "" : " (itself the nearest Ziegler-form fit of Hill + Armstrong-Frederick)") +
                "; there is no Bauschinger effect: after a reversal the reverse yield stress is too high by 2 X_RD "
                "(up to " + fixed(2.0 * xmax, 1) + " MPa), a difference that decays over a reverse strain of a few "
                "1/gamma.");
  }
  return n;
}

}  // namespace

std::string export_lsdyna(const MaterialCard& card, std::vector<std::string>* notes_out, const ExportOptions& o) {
  const ExportedLaw law = exported_law(card, o);
  const auto notes = lsdyna_notes(card, law, o);
  append(notes_out, notes);
  const auto& p = card.params;
  std::ostringstream os;
  write_header(os, "$ ", "LS-DYNA (keyword, units mm-t-s-N-MPa)", card, notes, 76);
  os << "*KEYWORD LONG=Y\n";
  if (!law.plastic) {
    os << "*MAT_ELASTIC_TITLE\n" << deck_material_name(card) << "\n";
    os << labels({"MID", "RO", "E", "PR"});
    os << field(o.lsdyna_material_id) << field(card.density) << field(p.E) << field(p.nu) << "\n";
    os << "*END\n";
    return os.str();
  }
  os << "*MAT_HILL_3R_TITLE\n" << deck_material_name(card) << "\n";
  os << labels({"MID", "RO", "E", "PR", "HR", "P1", "P2"});
  os << field(o.lsdyna_material_id) << field(card.density) << field(p.E) << field(p.nu) << field(3.0) << field(0.0)
     << field(0.0) << "\n";
  os << labels({"R00", "R45", "R90", "LCID", "E0"});
  os << field(law.lankford.r0) << field(law.lankford.r45) << field(law.lankford.r90) << field(o.lsdyna_curve_id)
     << field(0.0) << "\n";
  os << labels({"AOPT"});
  os << field(2.0) << "\n";
  os << labels({"", "", "", "A1", "A2", "A3"});
  os << blank() << blank() << blank() << field(1.0) << field(0.0) << field(0.0) << "\n";
  os << labels({"V1", "V2", "V3", "D1", "D2", "D3", "BETA"});
  os << field(0.0) << field(0.0) << field(0.0) << field(0.0) << field(1.0) << field(0.0) << field(0.0) << "\n";
  os << "*DEFINE_CURVE_TITLE\n" << deck_material_name(card) << " RD yield stress vs effective plastic strain\n";
  os << labels({"LCID", "SIDR", "SFA", "SFO", "OFFA", "OFFO", "DATTYP"});
  os << field(o.lsdyna_curve_id) << field(0) << field(1.0) << field(1.0) << field(0.0) << field(0.0) << field(0) << "\n";
  os << labels({"A1 (ebar)", "O1 (MPa)"});
  for (std::size_t i = 0; i < law.strain.size(); ++i) os << field(law.strain[i]) << field(law.monotonic[i]) << "\n";
  os << "*END\n";
  return os.str();
}

namespace {

std::vector<std::string> calculix_notes(const MaterialCard& card, const ExportedLaw& law, const ExportOptions& o) {
  const bool combined = law.kinematic != KinematicLaw::none && o.calculix_combined_hardening;
  auto n = common_notes(card, law, o, combined ? "*CYCLIC HARDENING" : "*PLASTIC",
                        "CalculiX keeps the last value (perfectly plastic)");
  if (!card.params.plastic) return n;
  const material::Hill48 hill = card.hill();
  if (!hill.is_von_mises() && !proportional_to_von_mises(hill)) {
    const double h0 = material::uniaxial_stress_factor(hill, 0.0);
    const double h45 = material::uniaxial_stress_factor(hill, std::numbers::pi / 4);
    const double h90 = material::uniaxial_stress_factor(hill, std::numbers::pi / 2);
    n.push_back("APPROXIMATION: CalculiX's *PLASTIC is von Mises (its built-in ANISO_PLAS model has a von Mises yield "
                "too): the Hill anisotropy is dropped and the deck reproduces RD tension only. The card predicts r0/r45/"
                "r90 = " + fixed(law.lankford.r0, 3) + "/" + fixed(law.lankford.r45, 3) + "/" +
                fixed(law.lankford.r90, 3) + " and yield-stress ratios sigma45/sigma0 = " + fixed(h0 / h45, 4) +
                ", sigma90/sigma0 = " + fixed(h0 / h90, 4) + ", tau_xy/sigma0 = " +
                fixed(h0 / material::shear_stress_factor(hill), 4) + "; the deck gives r = 1, 1, 1 and 1/sqrt(3) = 0.5774 "
                "in shear.");
  }
  if (law.kinematic == KinematicLaw::none) return n;
  const std::string fit = law.kinematic_exact ? "" : " (itself the nearest Ziegler-form fit of Hill + Armstrong-Frederick)";
  if (!combined) {
    const double xmax = law.gamma > 0 ? law.C / law.gamma : rd_back_stress(law.C, law.gamma, o.max_plastic_strain);
    n.push_back("APPROXIMATION: kinematic hardening is written as its isotropic equivalent in monotonic RD tension: "
                "*PLASTIC = isotropic size + RD back-stress (C/gamma)(1 - exp(-gamma ebar)), C = " + num(law.C) +
                " MPa, gamma = " + num(law.gamma) + fit + ". Monotonic tension is reproduced; there is no Bauschinger "
                "effect: after a reversal the reverse yield stress is too high by 2 X_RD (up to " + fixed(2.0 * xmax, 1) +
                " MPa), a difference that decays over a reverse strain of a few 1/gamma. CalculiX's own combined "
                "hardening was measured worse (docs/exports.md).");
  } else {
    n.push_back("APPROXIMATION: CalculiX's combined hardening (*PLASTIC, HARDENING=COMBINED = kinematic curve sigma_0(0) "
                "+ (C/gamma)(1 - exp(-gamma ebar)), C = " + num(law.C) + " MPa, gamma = " + num(law.gamma) + fit +
                "; *CYCLIC HARDENING = isotropic size) moves the back-stress with the slope of the kinematic curve at the "
                "accumulated plastic strain, C exp(-gamma ebar), instead of C + gamma |X| after a reversal, and its "
                "finite-strain formulation stores the back-stress in the reference configuration (it keeps growing with "
                "the stretch). Measured for card C.8, one C3D8 element: monotonic tension to 0.2 off by up to 7.8 %; "
                "after reversing by 0.1 the stress is -14 MPa instead of -120 MPa (docs/exports.md).");
  }
  return n;
}

}  // namespace

std::string export_calculix(const MaterialCard& card, std::vector<std::string>* notes_out, const ExportOptions& o) {
  const ExportedLaw law = exported_law(card, o);
  const auto notes = calculix_notes(card, law, o);
  append(notes_out, notes);
  // CalculiX reads at most 20 characters per number.
  auto n20 = [](double v) { return format_real(v, 20); };
  std::ostringstream os;
  write_header(os, "** ", "CalculiX ccx (*MATERIAL block)", card, notes, 96);
  os << "*MATERIAL, NAME=" << deck_material_name(card) << "\n";
  os << "*ELASTIC\n" << n20(card.params.E) << ", " << n20(card.params.nu) << "\n";
  os << "*DENSITY\n" << n20(card.density) << "\n";
  if (law.plastic) {
    if (law.kinematic == KinematicLaw::none || !o.calculix_combined_hardening) {
      os << "** von Mises stress [MPa], equivalent plastic strain"
         << (law.kinematic == KinematicLaw::none ? "" : " (isotropic equivalent of the kinematic hardening)")
         << "\n*PLASTIC\n";
      for (std::size_t i = 0; i < law.strain.size(); ++i) {
        os << n20(law.monotonic[i]) << ", " << n20(law.strain[i]) << "\n";
      }
    } else {
      os << "** kinematic curve: von Mises stress [MPa], equivalent plastic strain\n*PLASTIC, HARDENING=COMBINED\n";
      for (std::size_t i = 0; i < law.strain.size(); ++i) {
        os << n20(law.size.front() + rd_back_stress(law.C, law.gamma, law.strain[i])) << ", " << n20(law.strain[i]) << "\n";
      }
      os << "** isotropic size: von Mises stress [MPa], equivalent plastic strain\n*CYCLIC HARDENING\n";
      for (std::size_t i = 0; i < law.strain.size(); ++i) os << n20(law.size[i]) << ", " << n20(law.strain[i]) << "\n";
    }
  }
  return os.str();
}

std::string export_card(const MaterialCard& card, ExportFormat format, std::vector<std::string>* notes,
                        const ExportOptions& options) {
  switch (format) {
    case ExportFormat::lsdyna: return export_lsdyna(card, notes, options);
    case ExportFormat::calculix: return export_calculix(card, notes, options);
    default: return export_abaqus(card, notes, options);
  }
}

}  // namespace spifit::reports
