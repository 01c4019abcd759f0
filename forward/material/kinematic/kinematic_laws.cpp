#include "forward/material/kinematic/kinematic_laws.hpp"

#include <stdexcept>

namespace spifit::material {
const std::vector<KinematicLawInfo>& kinematic_laws() {
  static const std::vector<KinematicLawInfo> laws = [] {
    std::vector<KinematicLawInfo> out;
    for_each_law<KinematicLawList>([&](auto law, int id) {
      using Law = decltype(law);
      out.push_back({id, Law::name, Law::input_prefix, Law::title, Law::coefficients(), &Law::saturation});
    });
    return out;
  }();
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
