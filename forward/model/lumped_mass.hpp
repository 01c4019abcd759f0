#pragma once
// Lumped (diagonal) mass of a shell model for explicit dynamics, Jetteur's diagonal matrix
// (thesis §6.2.3, eqs. 6.61-6.62): translational m_I (area share x thickness x density);
// rotational about the in-plane axes c m_I with c = max(t^2/12, S/18) (bending and membrane
// frequencies of a rectangular sheet, S the element area); about the normal (drilling) twice
// that.
#include <vector>

namespace spifit::model {

class ShellModel;

struct LumpedMass {
  std::vector<double> translational, rotational, drilling;  // per node [t, t mm^2]
};

// density [t/mm^3] (aluminium 2.7e-9), on the model's initial thickness and reference areas.
LumpedMass lumped_mass(const ShellModel& model, double density);

}  // namespace spifit::model
