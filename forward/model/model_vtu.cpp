#include "forward/model/model_vtu.hpp"

#include "forward/model/fe_model.hpp"

namespace spifit::model {

mesh::VtuFrame vtu_frame(const FeModel& model, const std::vector<std::string>& sensitivity_names, const std::vector<double>& sensitivity_values) {
  mesh::VtuFrame f;
  f.points = model.positions();
  mesh::VtuField u{"displacement", 3, {}};
  for (int n = 0; n < model.num_nodes(); ++n) {
    const Eigen::Vector3d un = model.displacement(n);
    u.values.insert(u.values.end(), {un.x(), un.y(), un.z()});
  }
  f.point_data = {u};
  const int count = model.sensitivity_count();
  if (count > 0 && static_cast<int>(sensitivity_names.size()) == count && static_cast<int>(sensitivity_values.size()) == count)
    for (int k = 0; k < count; ++k) {
      const std::string& name = sensitivity_names[static_cast<std::size_t>(k)];
      const double p = sensitivity_values[static_cast<std::size_t>(k)];
      mesh::VtuField d{"d(displacement)/d(" + name + ")", 3, {}}, scaled{name + "*d(displacement)/d(" + name + ")", 3, {}};
      for (int n = 0; n < model.num_nodes(); ++n) {
        const Eigen::Vector3d dn = model.position_sensitivity(n).col(k);
        d.values.insert(d.values.end(), {dn.x(), dn.y(), dn.z()});
        scaled.values.insert(scaled.values.end(), {p * dn.x(), p * dn.y(), p * dn.z()});
      }
      f.point_data.push_back(std::move(d));
      f.point_data.push_back(std::move(scaled));
    }
  model.family().add_vtu_data(model, &f);
  for (const auto& c : model.contributions()) c->add_cell_data(&f.cell_data);
  return f;
}

}  // namespace spifit::model
