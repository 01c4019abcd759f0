#pragma once
// The registry of isotropic hardening laws. A law is one header declaring its coefficients and
// its stress and slope as templates on the scalar type (swift_hardening.hpp is the model), plus
// its line in HardeningLawList below; card reading, validation, `spifit material show`, the
// named inputs of fits and sweeps, the return mapping and the FE-code exports then find it here
// (docs/design/architecture.md, "A new material law").
#include "forward/material/hardening/swift_hardening.hpp"
#include "forward/material/hardening/swift_voce_hardening.hpp"
#include "forward/material/hardening/voce_hardening.hpp"
#include "forward/material/law_registry.hpp"
#include "forward/material/material_params.hpp"

#include <initializer_list>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace spifit::material {

// One line per law; Swift stays first (the default of MaterialParams).
using HardeningLawList = std::tuple<SwiftHardening, VoceHardening, SwiftVoceHardening>;

inline constexpr int kHardeningLawCount = static_cast<int>(std::tuple_size_v<HardeningLawList>);

// Calls f(Law{}) for the law with this index.
template <typename F>
decltype(auto) visit_hardening_law(int law, F&& f) {
  return visit_law<HardeningLawList>(law, std::forward<F>(f));
}

// The index of a law in the registry: hardening_law_index<SwiftHardening>() == 0.
template <typename Law>
constexpr int hardening_law_index() {
  static_assert(Law::count <= kMaxHardeningCoefficients, "raise kMaxHardeningCoefficients");
  return law_index<HardeningLawList, Law>();
}

// A law's coefficients in its declared order: make_hardening<SwiftHardening>({K, eps0, n}).
template <typename Law, typename T = double>
Hardening<T> make_hardening(std::initializer_list<T> coefficients) {
  return make_law<Hardening<T>, hardening_law_index<Law>()>(coefficients);
}

// The yield stress sigma_F(p) of the card's law.
template <typename T>
T hardening_stress(const MaterialParams<T>& m, const T& p) {
  return visit_hardening_law(m.hardening.law, [&](auto law) { return decltype(law)::stress(m.hardening.c.data(), p); });
}
// d sigma_F / dp at p = p0 + dl, given s = hardening_stress(m, p0 + dl).
template <typename T>
T hardening_slope(const MaterialParams<T>& m, const T& p0, const T& dl, const T& s) {
  return visit_hardening_law(m.hardening.law, [&](auto law) { return decltype(law)::slope(m.hardening.c.data(), p0, dl, s); });
}

// What the card reader, the named inputs and the reports know of a law.
struct HardeningLawInfo {
  int id = 0;
  std::string name;             // card table and fit-name prefix: "swift"
  std::string title;            // "Swift"
  std::string formula;          // "sigma_F = K (eps0 + p)^n"
  std::string initial_formula;  // sigma_F(0): "K eps0^n"
  std::vector<HardeningCoefficient> coefficients;
};

// In registry order.
const std::vector<HardeningLawInfo>& hardening_laws();
const HardeningLawInfo& hardening_law(int id);
const HardeningLawInfo* find_hardening_law(const std::string& name);
// "[swift], [voce] or [swift_voce]"
std::string hardening_table_list();

// The same law's coefficients for sigma_F(p / h) / h: the RD-normalised curve of the FE decks.
void scale_hardening_strain(Hardening<double>& h, double factor);
// The smallest plastic strain the curve's shape depends on (Swift's eps0; infinite for Voce).
double hardening_resolution_strain(const Hardening<double>& h);
// No hardening at all: sigma_F(1) = sigma_F(0).
bool is_perfectly_plastic(const MaterialParams<double>& m);

}  // namespace spifit::material
