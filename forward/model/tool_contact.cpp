#include "forward/model/tool_contact.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/model/model_energies.hpp"
#include "forward/model/fe_model.hpp"
#include "forward/model/shell_family.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace spifit::model {

ToolContact::ToolContact(const mesh::Mesh& mesh, double radius, PathFunction path, const contact::ContactOptions& options,
                         double spin_per_load_factor)
    : ToolContact(mesh, ContactSurface{}, radius, std::move(path), options, spin_per_load_factor) {}

ToolContact::ToolContact(const mesh::Mesh& mesh, const ContactSurface& surface, double radius, PathFunction path,
                         const contact::ContactOptions& options, double spin_per_load_factor)
    : mesh_(&mesh), surface_(surface), path_(std::move(path)), spin_per_load_factor_(spin_per_load_factor) {
  if (!(radius > 0.0)) throw std::invalid_argument("tool radius must be > 0");
  if (!std::isfinite(spin_per_load_factor)) throw std::invalid_argument("tool spin must be finite");
  if (const std::string err = options.validate(); !err.empty()) throw std::invalid_argument("contact: " + err);
  if (surface.faces && options.surface == contact::ContactOptions::Surface::phong)
    throw std::invalid_argument("contact: surface = \"phong\" curves the facets with the shell's directors; solid elements take \"flat\"");
  if (surface.faces && surface.element.size() != surface.faces->quads.size())
    throw std::invalid_argument("contact: the surface's faces and their elements differ in number");
  contact_ = std::make_unique<contact::ShellContact>(contact_mesh(), options, 1);
  tools_.assign(1, contact::SphereTool{});
  tools_.front().radius = radius;
  const Eigen::Vector3d c = path_(0.0);
  place(c, c, Eigen::Vector3d::Zero());
}

void ToolContact::set_copies(const std::vector<double>& angles_deg) {
  for (double a : angles_deg)
    if (!std::isfinite(a) || std::abs(std::remainder(a, 360.0)) < 1e-9)
      throw std::invalid_argument("tool copy angle " + std::to_string(a) + " deg: must be finite and not a multiple of 360");
  copies_deg_ = angles_deg;
  rotations_.assign(1, Eigen::Matrix3d::Identity());
  for (double a : angles_deg)
    rotations_.push_back(Eigen::AngleAxisd(a * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix());
  contact_ = std::make_unique<contact::ShellContact>(contact_mesh(), contact_->options(), 1 + static_cast<int>(angles_deg.size()));
  if (sensitivities_) contact_->enable_sensitivities(slots_);
  const contact::SphereTool real = tools_.front();
  tools_.assign(1 + angles_deg.size(), real);
  place(real.centre_committed, real.centre, real.spin);
}

void ToolContact::place(const Eigen::Vector3d& centre_committed, const Eigen::Vector3d& centre, const Eigen::Vector3d& spin) {
  for (std::size_t i = 0; i < tools_.size(); ++i) {
    const Eigen::Matrix3d& R = rotations_[i];
    tools_[i].centre_committed = R * centre_committed;
    tools_[i].centre = R * centre;
    tools_[i].spin = R * spin;  // a spin about z is unchanged; any axis turns with the copy
  }
}

contact::ContactSummary ToolContact::summary_of_tool(int i) const { return contact_->committed_summary(i); }

// Force of a pie model on the real tool (virtual tools, thesis Fig. 8.4). With cyclic ties the
// pie P stands for every pie of the sheet: the state of the pie rotated by phi about z is the
// state of P rotated by phi. Copy c of the tool sits at R(phi_c) c_0 (c_0: the real tool's
// centre). Its contact with a point x of P is the image, through that symmetry, of the real
// tool's contact with the point y = R(-phi_c) x of the pie rotated by -phi_c: the geometry of
// (x, copy) is the geometry of (y, real tool) rotated by phi_c. So if the copy pushes x with the
// force f, the real tool pushes y with R(-phi_c) f, and the force of the real tool on the sheet
// is
//   F = F_0 + sum_c R(-phi_c) F_c = sum_c R_c^T F_c,
// with F_c the force of tool c on the points of P. A footprint that straddles the edge
// theta = 0 is split between the real tool (its part on P) and the copy at +gamma (the part on
// the pie below, seen on P near theta = gamma); the sum is the whole footprint. The force of a
// pie model is therefore the whole tool force, NOT 1 / (number of pies) of it: it must not be
// scaled by 360 / gamma. (Strictly, the pie model is the sheet formed by 360 / gamma tools at
// once, one per pie; it stands for a single tool as far as the tools do not influence each
// other through the sheet, the assumption of the thesis's pie models.)
contact::ContactSummary ToolContact::summary() const {
  contact::ContactSummary out;
  for (int i = 0; i < contact_->tools(); ++i) {
    const contact::ContactSummary s = contact_->committed_summary(i);
    out.force_on_sheet += rotations_[static_cast<std::size_t>(i)].transpose() * s.force_on_sheet;
    out.max_penetration = std::max(out.max_penetration, s.max_penetration);
    out.max_pressure = std::max(out.max_pressure, s.max_pressure);
    out.active_points += s.active_points;
    out.sticking_points += s.sticking_points;
  }
  return out;
}

double ToolContact::surface_penetration(const FeModel& model) const {
  double deepest = summary().max_penetration;
  if (surface_.faces) {
    const element::NodeVectors none{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    for (const mesh::Quad& q : surface_.faces->quads) {
      element::NodeVectors x;
      for (std::size_t i = 0; i < 4; ++i) x[i] = model.positions()[static_cast<std::size_t>(q[i])];
      for (const contact::SphereTool& tool : tools_)
        deepest = std::max(deepest, contact::ShellContact::surface_penetration(contact_->options(), x, none, 0.0, tool));
    }
    return deepest;
  }
  for (int e = 0; e < static_cast<int>(model.mesh().quads.size()); ++e) {
    element::NodeVectors x, d;
    corner_vectors(model.mesh().quads[static_cast<std::size_t>(e)], model.positions(), model.directors(), &x, &d);
    const double offset = 0.5 * model.element_thickness(e);
    for (const contact::SphereTool& tool : tools_)
      deepest = std::max(deepest, contact::ShellContact::surface_penetration(contact_->options(), x, d, offset, tool));
  }
  return deepest;
}

void ToolContact::begin_increment(double lambda0, double lambda1) {
  place(path_(lambda0), path_(lambda1), Eigen::Vector3d(0.0, 0.0, spin_per_load_factor_ * (lambda1 - lambda0)));
}

bool ToolContact::add(int e, const ElementConfiguration& c, element::Vec24* rp, element::Mat24* kp) {
  if (passive_) return false;
  bool touched = false;
  for (std::size_t i = 0; i < tools_.size(); ++i)
    touched |= contact_->element(e, c.x, c.d, c.x0, c.d0, c.half_thickness, tools_[i], rp, kp, nullptr, static_cast<int>(i));
  return touched;
}

void ToolContact::before_commit(const FeModel& model) {
  force_before_.clear();
  for (int i = 0; i < contact_->tools(); ++i) force_before_.push_back(contact_->committed_summary(i).force_on_sheet);
  thickness_before_.clear();
  if (surface_.faces) return;  // faces taken as they are: no offset to move
  for (int e = 0; e < model.num_elements(); ++e) thickness_before_.push_back(model.element_thickness(e));
}

// The tool-side surface sits h/2 from the mid-surface with the committed thickness h; when h
// changes at a commit (constant-volume update) that surface moves under the loaded contact
// points, and their penalty energy changes by about -(normal force) x (change of h/2) without
// any work (a plane-stress shell has no through-thickness stress to do it): the release is
// booked separately so that the energy balance closes (ModelEnergies).
void ToolContact::after_commit(const FeModel& model) {
  contact_->commit();
  const std::vector<double> fn = surface_.faces ? std::vector<double>{} : contact_->element_normal_force();
  for (int e = 0; e < static_cast<int>(fn.size()) && e < model.num_elements(); ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (fn[ue] != 0.0) offset_release_ -= fn[ue] * 0.5 * (model.element_thickness(e) - thickness_before_[ue]);
  }
  // The tools' work over the increment, trapezoidal rule on the force and the centre's move.
  for (std::size_t i = 0; i < tools_.size(); ++i) {
    const Eigen::Vector3d after = contact_->committed_summary(static_cast<int>(i)).force_on_sheet;
    work_ += 0.5 * (force_before_[i] + after).dot(tools_[i].centre - tools_[i].centre_committed);
  }
  for (auto& t : tools_) t.centre_committed = t.centre;
}

void ToolContact::revert() { contact_->revert(); }

void ToolContact::add_energies(ModelEnergies* en) const {
  en->external_work += work_;
  en->contact_stored += contact_->stored_energy();
  en->friction_dissipation += contact_->friction_dissipation();
  en->contact_offset_release += offset_release_;
}

void ToolContact::add_cell_data(std::vector<mesh::VtuField>* cell_data) const {
  if (!surface_.faces) {
    cell_data->push_back({"contact_pressure", 1, contact_->element_pressure()});
    return;
  }
  // One value per model element: each face's pressure on its element, zero elsewhere.
  std::vector<double> pressure(static_cast<std::size_t>(mesh_->num_elements()), 0.0);
  const std::vector<double> faces = contact_->element_pressure();
  for (std::size_t f = 0; f < faces.size(); ++f) {
    double& p = pressure[static_cast<std::size_t>(surface_.element[f])];
    p = std::max(p, faces[f]);
  }
  cell_data->push_back({"contact_pressure", 1, pressure});
}

void ToolContact::save_state(io::BinaryWriter& w) const {
  w.i64(static_cast<std::int64_t>(tools_.size()));
  for (const auto& t : tools_) {
    w.f64(t.radius);
    w.vec3(t.centre);
    w.vec3(t.centre_committed);
    w.vec3(t.spin);
  }
  contact_->save_state(w);
  w.f64(work_);
  w.f64(offset_release_);
}

void ToolContact::load_state(io::BinaryReader& r) {
  r.expect_count("tools (the real one and its copies)", static_cast<std::int64_t>(tools_.size()));
  for (auto& t : tools_) {
    t.radius = r.f64();
    t.centre = r.vec3();
    t.centre_committed = r.vec3();
    t.spin = r.vec3();
  }
  contact_->load_state(r);
  work_ = r.f64();
  offset_release_ = r.f64();
}

void ToolContact::save_sensitivities(io::BinaryWriter& w, int count) const {
  if (sensitivities_) contact_->save_sensitivities(w, count);
}

void ToolContact::load_sensitivities(io::BinaryReader& r, int count) {
  if (sensitivities_) contact_->load_sensitivities(r, count);
}

ToolContact& attach_tool(FeModel& model, double radius, ToolContact::PathFunction path, const contact::ContactOptions& options,
                         double spin_per_load_factor) {
  return model.add_contribution(
      std::make_unique<ToolContact>(model.mesh(), model.family().contact_surface(), radius, std::move(path), options, spin_per_load_factor));
}

void ToolContact::enable_sensitivities() {
  contact_->enable_sensitivities(slots_);
  sensitivities_ = true;
}

bool ToolContact::add_derivatives(int e, const ElementConfiguration& c, const ConfigurationDerivatives& dc, element::SensDofs* drp,
                                  Eigen::Matrix<double, 3, material::kSensitivitySlots>* tool_force, bool keep) {
  if (passive_) return false;
  contact::ShellContact::ConfigurationDerivatives cd;
  cd.p = dc.x_d;
  cd.p0 = dc.x0_d0;
  cd.offset = dc.half_thickness;
  bool touched = false;
  for (std::size_t i = 0; i < tools_.size(); ++i) {
    element::SensDofs di = element::SensDofs::Zero();
    if (!contact_->element_derivatives(e, c.x, c.d, c.x0, c.d0, c.half_thickness, tools_[i], cd, &di, keep, static_cast<int>(i))) continue;
    touched = true;
    *drp += di;
    // The force on the tool is the sum of the position rows (r = f_int - f_ext: the contact's
    // forces on the nodes are those the sheet exerts on the tool).
    Eigen::Matrix<double, 3, material::kSensitivitySlots> f = Eigen::Matrix<double, 3, material::kSensitivitySlots>::Zero();
    for (int I = 0; I < 4; ++I) f += di.middleRows<3>(6 * I);
    *tool_force += rotations_[i].transpose() * f;
  }
  return touched;
}

// Both contact surfaces (flat facets and Phong's) and every tool differentiate.
std::string ToolContact::sensitivity_refusal() const { return ""; }

}  // namespace spifit::model
