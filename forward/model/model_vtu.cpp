#include "forward/model/model_vtu.hpp"

#include "forward/model/fe_model.hpp"

namespace spifit::model {

mesh::VtuFrame vtu_frame(const FeModel& model) {
  mesh::VtuFrame f;
  f.points = model.positions();
  mesh::VtuField u{"displacement", 3, {}};
  for (int n = 0; n < model.num_nodes(); ++n) {
    const Eigen::Vector3d un = model.displacement(n);
    u.values.insert(u.values.end(), {un.x(), un.y(), un.z()});
  }
  f.point_data = {u};
  model.family().add_vtu_data(model, &f);
  for (const auto& c : model.contributions()) c->add_cell_data(&f.cell_data);
  return f;
}

}  // namespace spifit::model
