#include "forward/material/kinematic/kinematic_laws.hpp"

#include <stdexcept>

namespace spifit::material {
namespace {

template <std::size_t... I>
std::vector<KinematicLawInfo> make_infos(std::index_sequence<I...>) {
  std::vector<KinematicLawInfo> out;
  (out.push_back(KinematicLawInfo{static_cast<int>(I), std::tuple_element_t<I, KinematicLawList>::name,
                                  std::tuple_element_t<I, KinematicLawList>::input_prefix, std::tuple_element_t<I, KinematicLawList>::title,
                                  std::tuple_element_t<I, KinematicLawList>::coefficients(),
                                  &std::tuple_element_t<I, KinematicLawList>::saturation}),
   ...);
  return out;
}

}  // namespace

const std::vector<KinematicLawInfo>& kinematic_laws() {
  static const std::vector<KinematicLawInfo> laws = make_infos(std::make_index_sequence<kKinematicLawCount>());
  return laws;
}

const KinematicLawInfo& kinematic_law(int id) {
  if (id < 0 || id >= kKinematicLawCount) throw std::out_of_range("no kinematic law with index " + std::to_string(id));
  return kinematic_laws()[static_cast<std::size_t>(id)];
}

const KinematicLawInfo* find_kinematic_law(const std::string& name) {
  for (const auto& l : kinematic_laws())
    if (l.name == name || l.input_prefix == name) return &l;
  return nullptr;
}

std::string kinematic_law_name(int id) { return id < 0 ? "none" : kinematic_law(id).name; }

std::string kinematic_table_list() {
  std::string s;
  const auto& laws = kinematic_laws();
  for (std::size_t i = 0; i < laws.size(); ++i) s += (i == 0 ? "" : i + 1 == laws.size() ? " or " : ", ") + ("[" + laws[i].name + "]");
  return s;
}

}  // namespace spifit::material
