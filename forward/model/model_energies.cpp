#include "forward/model/model_energies.hpp"

#include "forward/model/fe_model.hpp"

namespace spifit::model {

ModelEnergies energy_account(const FeModel& model) {
  ModelEnergies out;
  out.external_work = model.load_work();
  model.family().add_energies(model, &out);
  for (const auto& c : model.contributions()) c->add_energies(&out);
  return out;
}

}  // namespace spifit::model
