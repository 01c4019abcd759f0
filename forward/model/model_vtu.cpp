#include "forward/model/model_vtu.hpp"

#include "forward/model/shell_model.hpp"

#include <algorithm>

namespace spifit::model {

mesh::VtuFrame vtu_frame(const ShellModel& model) {
  mesh::VtuFrame f;
  f.points = model.positions();
  mesh::VtuField u{"displacement", 3, {}}, dir{"director", 3, {}}, h{"thickness", 1, model.nodal_thickness()};
  for (int n = 0; n < model.num_nodes(); ++n) {
    const Eigen::Vector3d un = model.displacement(n);
    u.values.insert(u.values.end(), {un.x(), un.y(), un.z()});
    const Eigen::Vector3d& dn = model.director(n);
    dir.values.insert(dir.values.end(), {dn.x(), dn.y(), dn.z()});
  }
  f.point_data = {u, dir, h};
  const auto& rule = model.thickness_rule();
  const int layers = rule.zeta.empty() ? 0 : static_cast<int>(rule.zeta.size());
  mesh::VtuField eq_max{"eqps_max", 1, {}}, s_bot{"stress_bottom", 3, {}}, s_mid{"stress_middle", 3, {}}, s_top{"stress_top", 3, {}};
  for (int e = 0; e < model.num_elements(); ++e) {
    const auto& el = model.element(e);
    double pmax = 0.0;
    Eigen::Vector3d sb = Eigen::Vector3d::Zero(), sm = sb, st = sb;
    const double share = 1.0 / el.points();
    for (int p = 0; p < el.points(); ++p) {
      const auto& sec = el.section(p);
      for (int l = 0; l < layers; ++l) pmax = std::max(pmax, sec.layer_state(l).eqps);
      sb += share * sec.layer_state(0).stress;
      sm += share * sec.layer_state(layers / 2).stress;
      st += share * sec.layer_state(layers - 1).stress;
    }
    eq_max.values.push_back(pmax);
    for (const auto* v : {&sb, &sm, &st}) {
      auto& field = v == &sb ? s_bot : v == &sm ? s_mid : s_top;
      field.values.insert(field.values.end(), {(*v)(0), (*v)(1), (*v)(2)});
    }
  }
  f.cell_data = {eq_max, s_bot, s_mid, s_top};
  for (const auto& c : model.contributions()) c->add_cell_data(&f.cell_data);
  return f;
}

}  // namespace spifit::model
