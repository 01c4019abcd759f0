#pragma once
// The registry of kinematic hardening laws. A law is one header declaring its coefficients, its
// contribution to a return-mapping step, its plane-stress X_zz update and its decay rate as
// templates on the scalar type (armstrong_frederick.hpp is the model), plus its line in
// KinematicLawList below; the card reader, the named inputs, the return mapping and the reports
// find it here.
#include "forward/material/kinematic/armstrong_frederick.hpp"
#include "forward/material/kinematic/ziegler.hpp"
#include "forward/material/law_registry.hpp"

#include <initializer_list>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace spifit::material {

// One line per law.
using KinematicLawList = std::tuple<ArmstrongFrederick, Ziegler>;

inline constexpr int kKinematicLawCount = static_cast<int>(std::tuple_size_v<KinematicLawList>);

// Calls f(Law{}) for the law with this index (which must be one: check Kinematic::active()).
template <typename F>
decltype(auto) visit_kinematic_law(int law, F&& f) {
  return visit_law<KinematicLawList>(law, std::forward<F>(f));
}

// The index of a law in the registry: kinematic_law_index<Ziegler>() == 1.
template <typename Law>
constexpr int kinematic_law_index() {
  static_assert(Law::count <= kMaxKinematicCoefficients, "raise kMaxKinematicCoefficients");
  return law_index<KinematicLawList, Law>();
}

// Whether the card's kinematic law is Law.
template <typename Law, typename T>
bool is_kinematic(const Kinematic<T>& k) {
  return k.law == kinematic_law_index<Law>();
}

// A law's coefficients in its declared order: make_kinematic<Ziegler>({CA, GA}).
template <typename Law, typename T = double>
Kinematic<T> make_kinematic(std::initializer_list<T> coefficients) {
  return make_law<Kinematic<T>, kinematic_law_index<Law>()>(coefficients);
}

struct KinematicLawInfo {
  int id = 0;
  std::string name;          // card table: "armstrong_frederick"
  std::string input_prefix;  // fit names: "af"
  std::string title;         // "Armstrong-Frederick"
  std::vector<LawCoefficient> coefficients;
  std::string (*saturation)(const double* c) = nullptr;  // note for `material show`
};

// In registry order.
const std::vector<KinematicLawInfo>& kinematic_laws();
const KinematicLawInfo& kinematic_law(int id);
// By card table name or fit-name prefix ("armstrong_frederick" or "af"); null if none.
const KinematicLawInfo* find_kinematic_law(const std::string& name);
// "none" or the law's card table name.
std::string kinematic_law_name(int id);
// "[armstrong_frederick] or [ziegler]"
std::string kinematic_table_list();

}  // namespace spifit::material
