#pragma once
// Energy account of the committed state of an FE model [N mm], a check of a static implicit
// run (no kinetic energy). external_work = the work of the tool (and its copies) on the sheet,
// the trapezoidal sum over the increments of (f_old + f_new) / 2 . (change of the tool centre),
// plus the work of the nodal loads; a spinning tool's torque is not counted.
// contact_offset_release: the tool-side surface sits h/2 from the mid-surface with the
// committed thickness h; when h changes at a commit (constant-volume update) that surface
// moves under the loaded contact points and their penalty energy changes by about
// -(normal force) x (change of h/2) without any work: a plane-stress shell has no
// through-thickness stress to do that work. The balance
//   external_work = elastic + plastic + transverse_shear + contact_stored
//                   + friction_dissipation + contact_offset_release
// holds up to the trapezoidal rule's error (balance_error; docs/design/cone.md, "Energies").
namespace spifit::model {

class FeModel;

struct ModelEnergies {
  double external_work = 0.0, elastic = 0.0, plastic = 0.0, transverse_shear = 0.0;
  double contact_stored = 0.0, friction_dissipation = 0.0, contact_offset_release = 0.0, kinetic = 0.0;
  double damping = 0.0;  // work of an explicit run's damping forces (0 for implicit runs)
  double internal() const { return elastic + plastic + transverse_shear; }
  double balance_error() const {
    return external_work - internal() - contact_stored - friction_dissipation - contact_offset_release - kinetic - damping;
  }
};

// The account of the committed state: the elements' stored and dissipated energies
// (ElementFamily::add_energies), the nodal loads' work and each contribution's terms
// (ElementContribution::add_energies).
ModelEnergies energy_account(const FeModel& model);

}  // namespace spifit::model
