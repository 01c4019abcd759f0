#pragma once
// What the registries of material laws share (hardening/hardening_laws.hpp,
// kinematic/kinematic_laws.hpp): a law list is a std::tuple of law types, each with an `enum
// Coefficient { ..., count }`; a card names a law by its index in the list.
#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace spifit::material {

// Calls f(Law{}) for the law of List with this index (the last one for an index past the end).
template <typename List, int I = 0, typename F>
decltype(auto) visit_law(int law, F&& f) {
  using Law = std::tuple_element_t<I, List>;
  if constexpr (I + 1 == static_cast<int>(std::tuple_size_v<List>)) {
    return f(Law{});
  } else {
    if (law == I) return f(Law{});
    return visit_law<List, I + 1>(law, std::forward<F>(f));
  }
}

// The index of Law in List.
template <typename List, typename Law, int I = 0>
constexpr int law_index() {
  static_assert(I < static_cast<int>(std::tuple_size_v<List>), "not a registered law");
  if constexpr (std::is_same_v<Law, std::tuple_element_t<I, List>>) return I;
  else return law_index<List, Law, I + 1>();
}

// Calls f(Law{}, index) for every law of List, in order.
template <typename List, typename F>
void for_each_law(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) { (f(std::tuple_element_t<I, List>{}, static_cast<int>(I)), ...); }(
      std::make_index_sequence<std::tuple_size_v<List>>());
}

// The coefficients of a law in its declared order, into a law-and-coefficients holder
// (Hardening<T>, Kinematic<T>): make_law<Holder, Index>({...}).
template <typename Holder, int Index, typename T>
Holder make_law(std::initializer_list<T> coefficients) {
  Holder h{Index, {}};
  int i = 0;
  for (const T& c : coefficients) h[i++] = c;
  return h;
}

// What the registries' info lists share (HardeningLawInfo, KinematicLawInfo, YieldFunctionInfo,
// each with `name`): the entry of an index, throwing std::out_of_range "no <what> with index N";
// the entry of a card-table name (null if none); "[a], [b] or [c]".
template <typename Info>
const Info& law_info_at(const std::vector<Info>& laws, int id, const char* what) {
  if (id < 0 || id >= static_cast<int>(laws.size())) throw std::out_of_range(std::string("no ") + what + " with index " + std::to_string(id));
  return laws[static_cast<std::size_t>(id)];
}
template <typename Info>
const Info* find_law_info(const std::vector<Info>& laws, const std::string& name) {
  for (const auto& l : laws)
    if (l.name == name) return &l;
  return nullptr;
}
template <typename Info>
std::string law_table_list(const std::vector<Info>& laws) {
  std::string s;
  for (std::size_t i = 0; i < laws.size(); ++i) s += (i == 0 ? "" : i + 1 == laws.size() ? " or " : ", ") + ("[" + laws[i].name + "]");
  return s;
}

}  // namespace spifit::material
