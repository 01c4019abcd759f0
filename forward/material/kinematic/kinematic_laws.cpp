#include "forward/material/kinematic/kinematic_laws.hpp"

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

const KinematicLawInfo& kinematic_law(int id) { return law_info_at(kinematic_laws(), id, "kinematic law"); }

const KinematicLawInfo* find_kinematic_law(const std::string& name) {
  for (const auto& l : kinematic_laws())
    if (l.name == name || l.input_prefix == name) return &l;
  return nullptr;
}

std::string kinematic_law_name(int id) { return id < 0 ? "none" : kinematic_law(id).name; }

std::string kinematic_table_list() { return law_table_list(kinematic_laws()); }

}  // namespace spifit::material
