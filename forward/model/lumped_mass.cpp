#include "forward/model/lumped_mass.hpp"

#include "forward/model/shell_model.hpp"

#include <algorithm>

namespace spifit::model {

LumpedMass lumped_mass(const ShellModel& model, double density) {
  const auto nn = static_cast<std::size_t>(model.num_nodes());
  const double t = model.initial_thickness();
  LumpedMass m;
  m.translational.assign(nn, 0.0);
  m.rotational.assign(nn, 0.0);
  m.drilling.assign(nn, 0.0);
  for (int e = 0; e < model.num_elements(); ++e) {
    const double area = model.element(e).reference_area();
    const double mass = density * t * area / 4.0;
    const double inertia = mass * std::max(t * t / 12.0, area / 18.0);  // eq. 6.62
    for (int i : model.mesh().quads[static_cast<std::size_t>(e)]) {
      m.translational[static_cast<std::size_t>(i)] += mass;
      m.rotational[static_cast<std::size_t>(i)] += inertia;
      m.drilling[static_cast<std::size_t>(i)] += 2.0 * inertia;  // D6 = D4 + D5 (eq. 6.61)
    }
  }
  return m;
}

}  // namespace spifit::model
