#pragma once
// The rigid spherical forming tool as a contribution of the shell model: the tool's centre
// follows a path of the load factor, the contact with the sheet is contact::ShellContact
// (penalty pressure, regularised Coulomb friction, docs/design/contact.md), and on a pie model the
// contact also sees copies of the tool rotated about z by the pie angle (the "virtual tools" of
// thesis Fig. 8.4), each with its own contact point states. It keeps the tool's work on the
// sheet and the energy released by the moving contact surface (ModelEnergies).
#include "forward/contact/shell_contact.hpp"
#include "forward/model/element_contribution.hpp"
#include "forward/model/element_family.hpp"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

namespace spifit::model {

class ToolContact final : public ElementContribution {
 public:
  // Centre of the real tool at load factor lambda.
  using PathFunction = std::function<Eigen::Vector3d(double)>;
  // spin_per_load_factor: tool rotation about +z [rad] per unit of load factor (rpm x 2 pi / 60
  // x seconds per unit load factor); positive = counter-clockwise seen from above. Throws
  // std::invalid_argument for a radius <= 0, a non-finite spin or invalid contact options.
  ToolContact(const mesh::Mesh& mesh, double radius, PathFunction path, const contact::ContactOptions& options,
              double spin_per_load_factor = 0.0);
  // The same against a family's contact surface (ElementFamily::contact_surface) over the model
  // mesh `mesh`: with faces, the contact acts on them as they are, and the phong surface (which
  // curves facets with the shell's directors) is refused.
  ToolContact(const mesh::Mesh& mesh, const ContactSurface& surface, double radius, PathFunction path, const contact::ContactOptions& options,
              double spin_per_load_factor = 0.0);

  // Virtual tools of a pie model with cyclic ties: copies of the tool rotated about z by these
  // angles [deg], typically {+gamma, -gamma}, so that a footprint crossing one pie edge acts on
  // the other. Call before the first increment (the contact states are reset); an empty list
  // removes the copies. Angles must be finite and not multiples of 360.
  void set_copies(const std::vector<double>& angles_deg);
  const std::vector<double>& copies_deg() const { return copies_deg_; }
  const contact::SphereTool& tool() const { return tools_.front(); }  // the real tool

  // Committed contact: penetration and pressure are the largest over the real tool and its
  // copies; force_on_sheet is the force the REAL tool exerts on the (cyclic) sheet, the real
  // tool's own contact plus each copy's contact rotated back by the copy's angle (see
  // tool_contact.cpp). Without copies: the plain sum over the contact points.
  contact::ContactSummary summary() const;
  // Committed contact of tool i alone (0: the real tool; i >= 1: copy i - 1), in the sheet's
  // frame (not rotated back).
  contact::ContactSummary summary_of_tool(int i) const;
  // Force exerted BY the sheet ON the (real) tool, committed state.
  Eigen::Vector3d force() const { return -summary().force_on_sheet; }
  // Largest penetration of any tool into the committed tool-side surface, sampled over every
  // contact face (ShellContact::surface_penetration: a shell's mid-surface offset by half the
  // element's thickness along the directors, or the family's faces) and never below the
  // contact points' own.
  double surface_penetration(const FeModel& model) const;
  double work() const { return work_; }  // the tools' work on the sheet so far [N mm]
  // Passive: the tool moves and its geometry is there (surface_penetration) but it adds no
  // force (the MST contact of an explicit run makes the contact instead).
  void set_passive(bool passive) { passive_ = passive; }

  // ElementContribution
  std::string name() const override { return "tool_contact"; }
  // None: both surfaces (flat facets and Phong's) differentiate.
  std::string sensitivity_refusal() const override;
  // The penalty K_p and the friction coefficient mu as parameters of a run's sensitivities, in
  // these derivative slots (-1: not); set before FeModel::enable_sensitivities.
  void set_parameter_slots(const contact::ShellContact::ParameterSlots& slots) { slots_ = slots; }
  void enable_sensitivities() override;
  // Every tool's contact with the element (the real tool and its copies), the force of each
  // copy turned back onto the real tool as summary() does.
  bool add_derivatives(int e, const ElementConfiguration& c, const ConfigurationDerivatives& dc, element::SensDofs* drp,
                       Eigen::Matrix<double, 3, material::kSensitivitySlots>* tool_force, bool keep) override;
  void begin_increment(double lambda0, double lambda1) override;
  bool add(int e, const ElementConfiguration& c, element::Vec24* rp, element::Mat24* kp) override;
  void before_commit(const FeModel& model) override;
  void after_commit(const FeModel& model) override;
  void revert() override;
  void add_energies(ModelEnergies* energies) const override;
  void add_cell_data(std::vector<mesh::VtuField>* cell_data) const override;
  void save_state(io::BinaryWriter& w) const override;
  void load_state(io::BinaryReader& r) override;
  void save_sensitivities(io::BinaryWriter& w, int count) const override;
  void load_sensitivities(io::BinaryReader& r, int count) override;

 private:
  const mesh::Mesh* mesh_;          // the model's
  ContactSurface surface_;          // faces null: the shell's offset mid-surface, mesh_'s quadrilaterals
  const mesh::Mesh& contact_mesh() const { return surface_.faces ? *surface_.faces : *mesh_; }
  std::unique_ptr<contact::ShellContact> contact_;
  PathFunction path_;
  double spin_per_load_factor_ = 0.0;
  std::vector<contact::SphereTool> tools_{1};   // [0] the real tool, then its rotated copies
  std::vector<double> copies_deg_;
  std::vector<Eigen::Matrix3d> rotations_{Eigen::Matrix3d::Identity()};  // one per tool: [0] = identity
  double work_ = 0.0;            // committed work of the tools on the sheet [N mm]
  bool passive_ = false;
  contact::ShellContact::ParameterSlots slots_;  // set_parameter_slots
  bool sensitivities_ = false;                   // enable_sensitivities
  double offset_release_ = 0.0;  // ModelEnergies::contact_offset_release [N mm]
  // Set by before_commit for after_commit: each tool's committed force, each element's thickness.
  std::vector<Eigen::Vector3d> force_before_;
  std::vector<double> thickness_before_;
  // Moves the real tool and its copies (rotated centres and spin).
  void place(const Eigen::Vector3d& centre_committed, const Eigen::Vector3d& centre, const Eigen::Vector3d& spin);
};

// Adds a tool to the model (FeModel::add_contribution) and returns it.
ToolContact& attach_tool(FeModel& model, double radius, ToolContact::PathFunction path, const contact::ContactOptions& options,
                         double spin_per_load_factor = 0.0);

}  // namespace spifit::model
