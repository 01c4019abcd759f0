#include "forward/model/model_energies.hpp"

#include "forward/model/shell_model.hpp"

namespace spifit::model {

ModelEnergies energy_account(const ShellModel& model) {
  ModelEnergies out;
  out.external_work = model.load_work();
  for (int e = 0; e < model.num_elements(); ++e) {
    element::NodeVectors x, d;
    model.committed_corners(e, &x, &d);
    const element::ElementEnergy ee = model.element(e).energy(x, d);
    out.elastic += ee.elastic;
    out.plastic += ee.plastic;
    out.transverse_shear += ee.transverse_shear;
  }
  for (const auto& c : model.contributions()) c->add_energies(&out);
  return out;
}

}  // namespace spifit::model
