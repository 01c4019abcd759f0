#include "reports/card_export.hpp"

#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/material/yield/yield_functions.hpp"
#include "forward/scenes/material_point/material_point_run.hpp"
#include "reports/card_export_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <stdexcept>

namespace spifit::reports {

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

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double xv) {
  if (xv <= x.front()) return y.front();
  if (xv >= x.back()) return y.back();
  const auto it = std::upper_bound(x.begin(), x.end(), xv);
  const std::size_t i = static_cast<std::size_t>(it - x.begin());
  const double t = (xv - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

}  // namespace

namespace {
void tabulate(const material::MaterialParams<double>& p, const ExportOptions& o, ExportedLaw& law);
ExportedLaw exported_registered_yield(const MaterialCard& card, const ExportOptions& o);
}  // namespace

ExportedLaw exported_law(const MaterialCard& card, const ExportOptions& o) {
  std::string err;
  if (!o.IsValid(&err)) throw std::invalid_argument("ExportOptions: " + err);
  const auto& p = card.params;
  const material::Hill48 hill = card.hill();
  ExportedLaw law;
  if (p.yield.active()) return exported_registered_yield(card, o);
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
  law.kinematic = p.plastic ? p.kinematic.law : -1;
  if (!p.plastic) return law;

  if (law.kinematic == material::kinematic_law_index<material::Ziegler>()) {
    law.C = p.kinematic[material::Ziegler::CA] / (law.h * law.h);
    law.gamma = p.kinematic[material::Ziegler::GA] / law.h;
  } else if (law.kinematic == material::kinematic_law_index<material::ArmstrongFrederick>()) {
    const double k = (gh * gh + hill.G * hill.G + hill.H * hill.H) / (2.0 * gh);
    const double CX = p.kinematic[material::ArmstrongFrederick::CX], Xsat = p.kinematic[material::ArmstrongFrederick::Xsat];
    law.C = CX * Xsat * k / (law.h * law.h);
    law.gamma = CX / law.h;
    law.kinematic_exact = deck::proportional_to_von_mises(hill);
  } else if (law.kinematic >= 0) {
    throw std::invalid_argument("card " + card.name + ": kinematic law " + material::kinematic_law(law.kinematic).name +
                                " has no export to the FE codes yet (reports/card_export.cpp knows armstrong_frederick and ziegler)");
  }

  tabulate(p, o, law);
  return law;
}

namespace {

// The hardening tables of an exported law whose h, C and gamma are set.
void tabulate(const material::MaterialParams<double>& p, const ExportOptions& o, ExportedLaw& law) {
  const double h = law.h;
  auto size_at = [&](double e) { return material::hardening_stress(p, e / h) / h; };
  auto mono_at = [&](double e) { return size_at(e) + rd_back_stress(law.C, law.gamma, e); };
  const double e1 = std::min(o.first_plastic_strain, 0.1 * h * material::hardening_resolution_strain(p.hardening));
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
}

// A card with a registered yield function (Yld2000-2d): h is its sigma_eq of a unit RD
// uniaxial stress, the r-values come from its flow direction; no kinematic hardening is exported.
ExportedLaw exported_registered_yield(const MaterialCard& card, const ExportOptions& o) {
  const auto& p = card.params;
  ExportedLaw law;
  law.h = material::uniaxial_yield_factor(p, 0.0);
  law.lankford = {material::uniaxial_r_value(p, 0.0), material::uniaxial_r_value(p, std::numbers::pi / 4.0),
                  material::uniaxial_r_value(p, std::numbers::pi / 2.0)};
  law.plastic = p.plastic;
  if (!p.plastic) return law;
  if (p.kinematic.active())
    throw std::invalid_argument("card " + card.name + ": " + material::yield_function_title(p.yield.law) + " with kinematic hardening (" +
                                material::kinematic_law(p.kinematic.law).name + ") has no export: the codes' own kinematic models for it are other laws");
  tabulate(p, o, law);
  return law;
}

}  // namespace

MaterialCard exported_equivalent_card(const MaterialCard& card) {
  if (card.params.yield.active()) throw std::invalid_argument("card " + card.name + ": exported_equivalent_card serves Hill 1948 cards (the Abaqus deck)");
  const ExportedLaw law = exported_law(card);
  MaterialCard eq = card;
  eq.name = card.name + "_exported";
  material::Hill48 hill = card.hill();
  const double s = 1.0 / (law.h * law.h);
  hill.F *= s; hill.G *= s; hill.H *= s; hill.L *= s; hill.M *= s; hill.N *= s;
  eq.set_hill(hill);
  auto& p = eq.params;
  if (p.plastic) {
    material::scale_hardening_strain(p.hardening, law.h);
    if (law.kinematic >= 0) p.kinematic = material::make_kinematic<material::Ziegler>({law.C, law.gamma});
  }
  return eq;
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
