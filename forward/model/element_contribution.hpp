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
  // (docs/design/sensitivities.md); empty when it can: its forces then depend on the parameters
  // only through the nodes and the element's thickness (the offset of the tool-side surface).
  virtual std::string sensitivity_refusal() const { return name() + " has no parameter sensitivities"; }
  // Adds to d the derivatives of this contribution's forces rp on an element (as add() returned
  // them, at fixed nodes and thickness) with respect to its own parameters, in their sensitivity
  // slots; nothing when it has none.
  virtual void add_own_parameter_derivatives(const element::Vec24& rp, element::SensDofs* d) const {
    (void)rp;
    (void)d;
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
};

}  // namespace spifit::model
