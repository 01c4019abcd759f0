#pragma once
// An additive contribution to the residual and tangent of each shell element, evaluated at
// the element's trial configuration, which the model sums after the element's own forces (as
// MFEM's forms sum their integrators): contact with the tool (tool_contact.hpp) is one; any
// other boundary physics on the sheet's surface (a blank holder, a die) is another. The
// contribution owns its state (committed and trial) and follows the model's increments:
// begin_increment, revert, the two commit hooks, and checkpoints.
#include "forward/element/shell_q4.hpp"
#include "forward/mesh/vtu_writer.hpp"

#include <string>
#include <vector>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::model {

class FeModel;
struct ModelEnergies;

// The configuration of one element that a contribution sees: trial corners x, d (positions and
// unit directors), the committed ones x0, d0 (start of the increment), and half the element's
// committed thickness (the tool-side surface is the mid-surface offset by it along d).
struct ElementConfiguration {
  const element::NodeVectors& x;
  const element::NodeVectors& d;
  const element::NodeVectors& x0;
  const element::NodeVectors& d0;
  double half_thickness = 0.0;
};

class ElementContribution {
 public:
  virtual ~ElementContribution() = default;
  // A name for checkpoints and messages ("tool_contact").
  virtual std::string name() const = 0;
  // Start of every increment attempt (after revert), load factor lambda0 -> lambda1.
  virtual void begin_increment(double lambda0, double lambda1) = 0;
  // Adds the contribution of element e to rp and kp (kp may be null), in the shell's
  // p-variables (positions and directors, element::director_to_dofs turns them into nodal
  // forces and moments). Returns false when it adds nothing. Called concurrently for distinct e.
  virtual bool add(int e, const ElementConfiguration& c, element::Vec24* rp, element::Mat24* kp) = 0;
  // Why the contribution cannot take part in a run with parameter sensitivities
  // (docs/design/sensitivities.md); empty when it can: enable_sensitivities is then called before
  // the first increment, and add_derivatives gives its forces' derivatives.
  virtual std::string sensitivity_refusal() const { return name() + " has no parameter sensitivities"; }
  virtual void enable_sensitivities() {}
  // How an element's configuration moves with the parameters (a column per derivative slot):
  // its trial p-variables (null: held fixed, the pseudo-load), its committed ones and the half
  // thickness.
  struct ConfigurationDerivatives {
    const element::SensDofs* x_d = nullptr;
    element::SensDofs x0_d0 = element::SensDofs::Zero();
    material::SensitivityRow half_thickness = material::SensitivityRow::Zero();
  };
  // Adds to drp the derivative of add()'s rp on element e (at the trial state add() left) along
  // dc, its own parameters and history included, and to tool_force that of the force the sheet
  // exerts on the tool through it. keep: the converged increment's derivatives, which the
  // contribution keeps for commit (every element is visited); else the pseudo-load. Returns
  // false when it adds nothing. Called concurrently for distinct e.
  virtual bool add_derivatives(int e, const ElementConfiguration& c, const ConfigurationDerivatives& dc, element::SensDofs* drp,
                               Eigen::Matrix<double, 3, material::kSensitivitySlots>* tool_force, bool keep) {
    (void)e, (void)c, (void)dc, (void)drp, (void)tool_force, (void)keep;
    return false;
  }
  // Committing an increment: before_commit sees the model still at its last committed state
  // (positions, element sections), after_commit sees the new one.
  virtual void before_commit(const FeModel& model) = 0;
  virtual void after_commit(const FeModel& model) = 0;
  virtual void revert() = 0;
  // The contribution's terms of the energy account (model_energies.hpp) at the committed state.
  virtual void add_energies(ModelEnergies* energies) const = 0;
  // Cell data of the contribution for the VTU output (one value per element).
  virtual void add_cell_data(std::vector<mesh::VtuField>* cell_data) const = 0;
  // Committed state, bit-exact (checkpoints); io::ArchiveError on a mismatch.
  virtual void save_state(io::BinaryWriter& w) const = 0;
  virtual void load_state(io::BinaryReader& r) = 0;
  // The committed derivatives of its history, after enable_sensitivities (checkpoints of a run
  // with sensitivities; count: the run's parameters); nothing by default, a contribution without
  // history derivatives.
  virtual void save_sensitivities(io::BinaryWriter& w, int count) const { (void)w, (void)count; }
  virtual void load_sensitivities(io::BinaryReader& r, int count) { (void)r, (void)count; }
};

}  // namespace spifit::model
