#include "forward/material/hardening/hardening_laws.hpp"

namespace spifit::material {
const std::vector<HardeningLawInfo>& hardening_laws() {
  static const std::vector<HardeningLawInfo> laws = [] {
    std::vector<HardeningLawInfo> out;
    for_each_law<HardeningLawList>([&](auto law, int id) {
      using Law = decltype(law);
      out.push_back({id, Law::name, Law::title, Law::formula, Law::initial_formula, Law::coefficients()});
    });
    return out;
  }();
  return laws;
}

const HardeningLawInfo& hardening_law(int id) { return law_info_at(hardening_laws(), id, "hardening law"); }

const HardeningLawInfo* find_hardening_law(const std::string& name) { return find_law_info(hardening_laws(), name); }

std::string hardening_table_list() { return law_table_list(hardening_laws()); }

void scale_hardening_strain(Hardening<double>& h, double factor) {
  visit_hardening_law(h.law, [&](auto law) { decltype(law)::scale_strain(h.c.data(), factor); return 0; });
}

double hardening_resolution_strain(const Hardening<double>& h) {
  return visit_hardening_law(h.law, [&](auto law) { return decltype(law)::resolution_strain(h.c.data()); });
}

bool is_perfectly_plastic(const MaterialParams<double>& m) { return hardening_stress(m, 1.0) == hardening_stress(m, 0.0); }

}  // namespace spifit::material
