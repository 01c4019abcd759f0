#include "forward/model/shell_family.hpp"

#include "forward/element/director.hpp"
#include "forward/element/director_dofs.hpp"
#include "forward/mesh/extruded_sheet.hpp"
#include "forward/mesh/vtu_writer.hpp"
#include "forward/model/material_axes.hpp"
#include "forward/model/element_contribution.hpp"
#include "forward/model/fe_model.hpp"
#include "forward/model/model_energies.hpp"
#include "forward/model/rotation_frames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace spifit::model {

void corner_vectors(const mesh::Quad& q, const std::vector<Eigen::Vector3d>& xs, const std::vector<Eigen::Vector3d>& ds,
                    element::NodeVectors* x, element::NodeVectors* d) {
  for (std::size_t i = 0; i < 4; ++i) {
    (*x)[i] = xs[static_cast<std::size_t>(q[i])];
    (*d)[i] = ds[static_cast<std::size_t>(q[i])];
  }
}

bool material_axes_from_string(const std::string& s, ShellModelOptions::MaterialAxes* axes) {
  if (s == "fixed") { *axes = ShellModelOptions::MaterialAxes::fixed; return true; }
  if (s == "polar") { *axes = ShellModelOptions::MaterialAxes::polar; return true; }
  return false;
}

const char* to_string(ShellModelOptions::MaterialAxes axes) { return axes == ShellModelOptions::MaterialAxes::polar ? "polar" : "fixed"; }

ShellFamily::ShellFamily(const mesh::Mesh& mesh, double thickness, const material::MaterialParams<double>& material,
                         const ShellModelOptions& options)
    : mesh_(&mesh), options_(options), law_(material), rule_(element::make_thickness_rule(options.shell.thickness_rule, options.shell.thickness_points)),
      thickness_(thickness) {
  if (!(thickness > 0.0)) throw std::invalid_argument("thickness must be > 0, got " + std::to_string(thickness));
  if (!mesh.hexes.empty()) throw std::invalid_argument("the shell needs a mesh of quadrilaterals; this one has " + std::to_string(mesh.hexes.size()) + " hexahedra");
  check_geometry(mesh, thickness);
  build_directors_and_elements(mesh, thickness);
}

// Node references in range, and the thickness over the shortest edge of each element against
// the limits of the options.
void ShellFamily::check_geometry(const mesh::Mesh& mesh, double thickness) {
  const int nn = mesh.num_nodes(), ne = mesh.num_elements();
  if (ne == 0) throw std::invalid_argument("the mesh has no element");
  for (int e = 0; e < ne; ++e)
    for (int i : mesh.quads[static_cast<std::size_t>(e)])
      if (i < 0 || i >= nn) throw std::invalid_argument("element " + std::to_string(e) + " refers to node " + std::to_string(i) + " out of range");
  int worst = -1;
  for (int e = 0; e < ne; ++e) {
    const auto& q = mesh.quads[static_cast<std::size_t>(e)];
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < 4; ++i)
      shortest = std::min(shortest, (mesh.nodes[static_cast<std::size_t>(q[(i + 1) % 4])] - mesh.nodes[static_cast<std::size_t>(q[i])]).norm());
    if (!(shortest > 0.0)) throw std::invalid_argument("element " + std::to_string(e) + " has a zero-length edge");
    if (thickness / shortest > max_t_over_l_) {
      max_t_over_l_ = thickness / shortest;
      worst = e;
    }
  }
  char buf[200];
  if (max_t_over_l_ > options_.max_thickness_over_length) {
    std::snprintf(buf, sizeof buf, "thickness over element length t/l = %.3g at element %d exceeds %.3g: refine less or use a solid-shell",
                  max_t_over_l_, worst, options_.max_thickness_over_length);
    throw std::invalid_argument(buf);
  }
  if (max_t_over_l_ > options_.warn_thickness_over_length) {
    std::snprintf(buf, sizeof buf, "t/l = %.3g at element %d is above %.3g: transverse shear and thickness stress matter there (the thesis's fine cone mesh has 1.7)",
                  max_t_over_l_, worst, options_.warn_thickness_over_length);
    warnings_.emplace_back(buf);
  }
}

// Nodal directors: normalised sum of the normals of the elements around each node (the
// diagonal cross product, which weights by area); then the elements.
void ShellFamily::build_directors_and_elements(const mesh::Mesh& mesh, double thickness) {
  const int ne = mesh.num_elements();
  d0_ = mesh::nodal_normals(mesh);
  elements_.reserve(static_cast<std::size_t>(ne));
  for (int e = 0; e < ne; ++e) {
    const auto& q = mesh.quads[static_cast<std::size_t>(e)];
    element::NodeVectors X, D;
    corner_vectors(q, mesh.nodes, d0_, &X, &D);
    element::ShellOptions shell = options_.shell;
    if (options_.material_axes == ShellModelOptions::MaterialAxes::polar) shell.material_axis = polar_material_axis(0.25 * (X[0] + X[1] + X[2] + X[3]), options_.shell.material_axis);
    try {
      elements_.emplace_back(X, D, thickness, law_, rule_, shell);
    } catch (const std::invalid_argument& err) {
      throw std::invalid_argument("element " + std::to_string(e) + ": " + err.what());
    }
  }
}

std::vector<int> ShellFamily::element_nodes(int e) const {
  const auto& q = mesh_->quads[static_cast<std::size_t>(e)];
  return {q.begin(), q.end()};
}

double ShellFamily::element_thickness(int e) const {
  const element::ShellQ4& el = elements_[static_cast<std::size_t>(e)];
  double h = 0.0;
  for (int p = 0; p < el.points(); ++p) h += el.section(p).thickness();
  return h / el.points();
}

namespace {

// An element's failure as the solver reports it: where (element, in-plane point, layer) and why.
solver::ElementEvaluation element_failure(int e, const element::ElementStatus& s) {
  solver::ElementEvaluation out;
  out.ok = false;
  out.reason = s.reason;
  out.suggested_scale = s.suggested_scale;
  out.where = "element " + std::to_string(e);
  if (s.point >= 0) out.where += ", in-plane point " + std::to_string(s.point);
  if (s.layer >= 0) out.where += ", layer " + std::to_string(s.layer);
  return out;
}

}  // namespace

solver::ElementEvaluation ShellFamily::evaluate(int e, const ElementInputs& in, Eigen::VectorXd* re, Eigen::MatrixXd* ke) {
  const auto& q = mesh_->quads[static_cast<std::size_t>(e)];
  element::NodeVectors x, d;
  corner_vectors(q, in.x, in.d, &x, &d);
  element::Vec24 r;
  element::Mat24 k;
  const element::ElementStatus s = elements_[static_cast<std::size_t>(e)].compute(x, d, &r, ke ? &k : nullptr);
  solver::ElementEvaluation out;
  if (!s.ok) return element_failure(e, s);
  if (!in.contributions.empty()) {
    // The contributions add in the p-variables (positions and directors), turned into nodal
    // forces and moments once.
    element::Vec24 rc = element::Vec24::Zero();
    element::Mat24 kc = element::Mat24::Zero();
    element::NodeVectors x0, d0;
    corner_vectors(q, in.x0, in.d0, &x0, &d0);
    const ElementConfiguration config{x, d, x0, d0, 0.5 * element_thickness(e)};
    bool touched = false;
    for (auto& c : in.contributions) touched |= c->add(e, config, &rc, ke ? &kc : nullptr);
    if (touched) {
      element::Vec24 ru;
      element::Mat24 ku;
      element::director_to_dofs(d, rc, ke ? &kc : nullptr, &ru, ke ? &ku : nullptr);
      r += ru;
      if (ke) k += ku;
    }
  }
  if (!in.frames.empty()) {
    // Rotation rows and columns of framed nodes into their frames at the trial directors.
    for (int I = 0; I < 4; ++I) {
      if (!in.frames.framed(q[static_cast<std::size_t>(I)])) continue;
      const Eigen::Matrix3d f = in.frames.frame(q[static_cast<std::size_t>(I)], d[static_cast<std::size_t>(I)]);
      const int o = 6 * I + 3;
      r.segment<3>(o) = (f.transpose() * r.segment<3>(o)).eval();
      if (ke) {
        k.middleRows<3>(o) = (f.transpose() * k.middleRows<3>(o)).eval();
        k.middleCols<3>(o) = (k.middleCols<3>(o) * f).eval();
      }
    }
  }
  *re = r;
  if (ke) *ke = k;
  return out;
}

void ShellFamily::commit() {
  for (auto& el : elements_) el.commit();
}

void ShellFamily::revert() {
  for (auto& el : elements_) el.revert();
}

void ShellFamily::add_energies(const FeModel& model, ModelEnergies* out) const {
  for (int e = 0; e < num_elements(); ++e) {
    element::NodeVectors x, d;
    corner_vectors(mesh_->quads[static_cast<std::size_t>(e)], model.positions(), model.directors(), &x, &d);
    const element::ElementEnergy ee = elements_[static_cast<std::size_t>(e)].energy(x, d);
    out->elastic += ee.elastic;
    out->plastic += ee.plastic;
    out->transverse_shear += ee.transverse_shear;
  }
}

void ShellFamily::add_vtu_data(const FeModel& model, mesh::VtuFrame* frame) const {
  mesh::VtuField dir{"director", 3, {}}, h{"thickness", 1, model.nodal_thickness()};
  for (int n = 0; n < model.num_nodes(); ++n) {
    const Eigen::Vector3d& dn = model.director(n);
    dir.values.insert(dir.values.end(), {dn.x(), dn.y(), dn.z()});
  }
  frame->point_data.push_back(std::move(dir));
  frame->point_data.push_back(std::move(h));
  const int layers = rule_.zeta.empty() ? 0 : static_cast<int>(rule_.zeta.size());
  mesh::VtuField eq_max{"eqps_max", 1, {}}, s_bot{"stress_bottom", 3, {}}, s_mid{"stress_middle", 3, {}}, s_top{"stress_top", 3, {}};
  for (const element::ShellQ4& el : elements_) {
    double pmax = 0.0;
    Eigen::Vector3d sb = Eigen::Vector3d::Zero(), sm = sb, st = sb;
    const double share = 1.0 / el.points();
    for (int p = 0; p < el.points(); ++p) {
      const auto& sec = el.section(p);
      for (int l = 0; l < layers; ++l) pmax = std::max(pmax, sec.layer_state(l).eqps);
      sb += share * sec.layer_state(0).stress;
      sm += share * sec.layer_state(layers / 2).stress;
      st += share * sec.layer_state(layers - 1).stress;
    }
    eq_max.values.push_back(pmax);
    for (const auto* v : {&sb, &sm, &st}) {
      auto& field = v == &sb ? s_bot : v == &sm ? s_mid : s_top;
      field.values.insert(field.values.end(), {(*v)(0), (*v)(1), (*v)(2)});
    }
  }
  for (auto* f : {&eq_max, &s_bot, &s_mid, &s_top}) frame->cell_data.push_back(std::move(*f));
}

void ShellFamily::save_state(io::BinaryWriter& w) const {
  for (const auto& el : elements_) el.save_state(w);
}

void ShellFamily::load_state(io::BinaryReader& r) {
  for (auto& el : elements_) el.load_state(r);
}

bool ShellFamily::tangent_was_exact() const {
  for (const auto& el : elements_)
    if (!el.tangent_was_exact()) return false;
  return true;
}

void ShellFamily::set_exact_tangents(bool exact) {
  for (auto& el : elements_) el.set_exact_tangents(exact);
}

void ShellFamily::save_sensitivities(io::BinaryWriter& w) const {
  for (const auto& el : elements_) el.save_sensitivities(w, sensitivity_count_);
}

void ShellFamily::load_sensitivities(io::BinaryReader& r) {
  for (auto& el : elements_) el.load_sensitivities(r, sensitivity_count_);
}

void ShellFamily::enable_sensitivities(const material::MaterialParams<material::SensitivityScalar>& law, int count) {
  sensitivity_count_ = count;
  material::ReturnMappingOptions o;
  o.single_jet_evaluation = true;
  sensitivity_law_ = std::make_unique<element::SensLaw>(law, o);
  // Up to three parameters and a layer's three strain slots fit narrower Jets (sensitivities.md, Cost).
  narrow_laws_ = element::NarrowLaws(law, o, count);
  for (auto& el : elements_) el.enable_sensitivities(count);
}

material::SensitivityRow ShellFamily::offset_sensitivity(int e) const {
  const element::ShellQ4& el = elements_[static_cast<std::size_t>(e)];
  material::SensitivityRow d = material::SensitivityRow::Zero();
  for (int p = 0; p < el.points(); ++p) d += el.section(p).thickness_sensitivity();
  return (0.5 / el.points()) * d;
}

bool ShellFamily::contribution_derivatives(int e, const ElementInputs& in, const element::NodeVectors& x, const element::NodeVectors& d,
                                           const element::SensDofs& du0, const element::SensDofs* du, element::SensDofs* drc,
                                           Eigen::Matrix<double, 3, material::kSensitivitySlots>* tool_force) const {
  drc->setZero();
  tool_force->setZero();
  if (in.contributions.empty()) return false;
  const auto& q = mesh_->quads[static_cast<std::size_t>(e)];
  element::NodeVectors x0, d0;
  corner_vectors(q, in.x0, in.d0, &x0, &d0);
  const ElementConfiguration config{x, d, x0, d0, 0.5 * element_thickness(e)};
  ElementContribution::ConfigurationDerivatives dc;
  element::SensDofs dp;
  if (du) {
    dp = element::director_variable_derivatives(d, *du);
    dc.x_d = &dp;
  }
  dc.x0_d0 = element::director_variable_derivatives(d0, du0);
  dc.half_thickness = offset_sensitivity(e);
  bool touched = false;
  for (const auto& c : in.contributions) touched |= c->add_derivatives(e, config, dc, drc, tool_force, du != nullptr);
  return touched;
}

solver::ElementEvaluation ShellFamily::sensitivity_load(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, Eigen::MatrixXd* load) {
  const auto& q = mesh_->quads[static_cast<std::size_t>(e)];
  element::NodeVectors x, d;
  corner_vectors(q, in.x, in.d, &x, &d);
  element::SensDofs l;
  const element::ElementStatus s = elements_[static_cast<std::size_t>(e)].sensitivities(x, d, *sensitivity_law_, nullptr, &l, sensitivity_count_, &narrow_laws_);
  if (!s.ok) return element_failure(e, s);
  element::SensDofs drc;
  Eigen::Matrix<double, 3, material::kSensitivitySlots> force;
  if (contribution_derivatives(e, in, x, d, du0, nullptr, &drc, &force)) {
    // The moment rows are d x r_d: linear in the p-variables' forces, column by column.
    const element::SensDofs dru = element::director_force_derivatives(d, drc, sensitivity_count_);
    for (int k = 0; k < sensitivity_count_; ++k) l.col(k) += dru.col(k);
  }
  *load = l;
  return {};
}

solver::ElementEvaluation ShellFamily::update_sensitivities(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, const Eigen::MatrixXd& du,
                                                            Eigen::Matrix<double, 3, material::kSensitivitySlots>* contribution_force) {
  const auto& q = mesh_->quads[static_cast<std::size_t>(e)];
  element::NodeVectors x, d;
  corner_vectors(q, in.x, in.d, &x, &d);
  const element::SensDofs dus = du;
  const element::ElementStatus s = elements_[static_cast<std::size_t>(e)].sensitivities(x, d, *sensitivity_law_, &dus, nullptr, sensitivity_count_, &narrow_laws_);
  if (!s.ok) return element_failure(e, s);
  // Every element, so that the contributions keep their trial derivatives (zero out of reach).
  element::SensDofs drc;
  Eigen::Matrix<double, 3, material::kSensitivitySlots> force;
  contribution_derivatives(e, in, x, d, du0, &dus, &drc, &force);
  if (contribution_force) *contribution_force = force;
  return {};
}

}  // namespace spifit::model
