#include "forward/model/solid_family.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/model/element_contribution.hpp"
#include "forward/mesh/vtu_writer.hpp"
#include "forward/model/fe_model.hpp"
#include "forward/model/material_axes.hpp"
#include "forward/model/model_energies.hpp"

#include <cmath>
#include <stdexcept>

namespace spifit::model {

namespace {
element::HexCorners corners(const mesh::Hex& h, const std::vector<Eigen::Vector3d>& xs) {
  element::HexCorners x;
  for (std::size_t I = 0; I < 8; ++I) x[I] = xs[static_cast<std::size_t>(h[I])];
  return x;
}
}  // namespace

SolidFamily::SolidFamily(const mesh::Mesh& mesh, const material::MaterialParams<double>& material, const SolidOptions& options)
    : mesh_(&mesh), law_(material), kind_(options.element), layers_(options.layers) {
  if (!mesh.quads.empty())
    throw std::invalid_argument("the " + name() + " needs a mesh of hexahedra; this one has " + std::to_string(mesh.quads.size()) + " quadrilaterals");
  const int ne = static_cast<int>(mesh.hexes.size());
  if (ne == 0) throw std::invalid_argument("the mesh has no hexahedron");
  if (options.layers < 1) throw std::invalid_argument("a " + name() + " sheet needs at least one layer, got " + std::to_string(options.layers));
  if (kind_ == SolidElementKind::solid_shell && options.layers != 1)
    throw std::invalid_argument("a solid-shell sheet has one element through the thickness, got " + std::to_string(options.layers) + " layers");
  if (ne % options.layers != 0)
    throw std::invalid_argument(std::to_string(ne) + " hexahedra are not " + std::to_string(options.layers) + " equal layers");
  if (!(options.material_axis.allFinite() && options.material_axis.norm() > 0.0)) throw std::invalid_argument("the rolling direction must be a non-zero vector");
  elements_.reserve(static_cast<std::size_t>(ne));
  height0_.reserve(static_cast<std::size_t>(ne));
  for (int e = 0; e < ne; ++e) {
    const mesh::Hex& h = mesh.hexes[static_cast<std::size_t>(e)];
    for (int i : h)
      if (i < 0 || i >= mesh.num_nodes()) throw std::invalid_argument("element " + std::to_string(e) + " refers to node " + std::to_string(i) + " out of range");
    const element::HexCorners X = corners(h, mesh.nodes);
    Eigen::Vector3d bottom = Eigen::Vector3d::Zero(), top = Eigen::Vector3d::Zero();
    for (std::size_t I = 0; I < 4; ++I) {
      bottom += 0.25 * X[I];
      top += 0.25 * X[I + 4];
    }
    const double height = (top - bottom).norm();
    if (!(height > 0.0)) throw std::invalid_argument("element " + std::to_string(e) + " has no height between its bottom and top faces");
    const Eigen::Vector3d n = (top - bottom) / height;
    const Eigen::Vector3d a = options.material_axes == ShellModelOptions::MaterialAxes::polar
                                  ? polar_material_axis(0.5 * (bottom + top), options.material_axis)
                                  : Eigen::Vector3d(options.material_axis);
    const Eigen::Vector3d in_plane = a - a.dot(n) * n;
    if (!(in_plane.norm() > 1e-6 * a.norm()))
      throw std::invalid_argument("element " + std::to_string(e) + ": the rolling direction lies along the sheet normal");
    Eigen::Matrix3d axes;
    axes.col(0) = in_plane.normalized();
    axes.col(1) = n.cross(axes.col(0));
    axes.col(2) = n;
    try {
      if (kind_ == SolidElementKind::brick) elements_.push_back(std::make_unique<element::Brick8>(X, axes, law_, options.hourglass));
      else elements_.push_back(std::make_unique<element::SolidShell8>(X, axes, law_, options.thickness_rule, options.enhanced_tolerance));
    } catch (const std::invalid_argument& err) {
      throw std::invalid_argument("element " + std::to_string(e) + ": " + err.what());
    }
    height0_.push_back(height);
  }
  face_of_element_.assign(static_cast<std::size_t>(ne), -1);
  if (mesh.face_sets.count("top")) {
    top_ = mesh::face_surface(mesh, "top");
    for (std::size_t f = 0; f < top_.element.size(); ++f) {
      if (top_.face[f] != 1)
        throw std::invalid_argument("face set 'top': element " + std::to_string(top_.element[f]) + " has face " + std::to_string(top_.face[f]) +
                                    " in it; the " + name() + "'s tool side is its face 1 (corners 4-7)");
      face_of_element_[static_cast<std::size_t>(top_.element[f])] = static_cast<int>(f);
    }
  }
}

std::string SolidFamily::name() const { return kind_ == SolidElementKind::brick ? "brick" : "solid_shell"; }

const element::Brick8& SolidFamily::brick(int e) const {
  if (kind_ != SolidElementKind::brick) throw std::logic_error("element " + std::to_string(e) + " is a " + name() + ", not a brick");
  return static_cast<const element::Brick8&>(element(e));
}

const element::SolidShell8& SolidFamily::solid_shell(int e) const {
  if (kind_ != SolidElementKind::solid_shell) throw std::logic_error("element " + std::to_string(e) + " is a " + name() + ", not a solid-shell");
  return static_cast<const element::SolidShell8&>(element(e));
}

ContactSurface SolidFamily::contact_surface() const {
  if (top_.element.empty()) throw std::invalid_argument("the solid mesh has no face set 'top' for the tool to touch");
  return ContactSurface{&top_.mesh, top_.element};
}

std::vector<int> SolidFamily::element_nodes(int e) const {
  const mesh::Hex& h = mesh_->hexes[static_cast<std::size_t>(e)];
  return {h.begin(), h.end()};
}

solver::ElementEvaluation SolidFamily::evaluate(int e, const ElementInputs& in, Eigen::VectorXd* re, Eigen::MatrixXd* ke) {
  element::HexVector f;
  element::HexMatrix k;
  const element::PointStatus s = elements_[static_cast<std::size_t>(e)]->evaluate(corners(mesh_->hexes[static_cast<std::size_t>(e)], in.x), &f, ke ? &k : nullptr);
  solver::ElementEvaluation out;
  if (!s.ok) {
    out.ok = false;
    out.reason = s.reason;
    out.suggested_scale = s.suggested_scale;
    out.where = name() + " element " + std::to_string(e);
    return out;
  }
  const int face = face_of_element_[static_cast<std::size_t>(e)];
  if (face >= 0 && !in.contributions.empty()) {
    // The top face's corners are the element's nodes 4-7 in order (mesh::hex_face_corners(1)).
    const mesh::Hex& h = mesh_->hexes[static_cast<std::size_t>(e)];
    element::NodeVectors x, x0;
    const element::NodeVectors none{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    for (std::size_t I = 0; I < 4; ++I) {
      x[I] = in.x[static_cast<std::size_t>(h[I + 4])];
      x0[I] = in.x0[static_cast<std::size_t>(h[I + 4])];
    }
    const ElementConfiguration config{x, none, x0, none, 0.0};
    element::Vec24 rp = element::Vec24::Zero();
    element::Mat24 kp = element::Mat24::Zero();
    bool touched = false;
    for (auto& c : in.contributions) touched |= c->add(face, config, &rp, ke ? &kp : nullptr);
    if (touched) {
      // p = (x_I, d_I) per corner; with no offset only the positions' parts are non-zero.
      for (int I = 0; I < 4; ++I) {
        f.segment<3>(3 * (I + 4)) += rp.segment<3>(6 * I);
        if (ke)
          for (int J = 0; J < 4; ++J) k.block<3, 3>(3 * (I + 4), 3 * (J + 4)) += kp.block<3, 3>(6 * I, 6 * J);
      }
    }
  }
  *re = f;
  if (ke) *ke = k;
  return out;
}

void SolidFamily::commit() {
  for (auto& el : elements_) el->commit();
}

void SolidFamily::revert() {
  for (auto& el : elements_) el->revert();
}

double SolidFamily::element_thickness(int e) const {
  const int per_layer = num_elements() / layers_;
  const int q = e % per_layer;
  double h = 0.0;
  for (int l = 0; l < layers_; ++l) {
    const auto k = static_cast<std::size_t>(l * per_layer + q);
    h += height0_[k] * elements_[k]->thickness_ratio();
  }
  return h;
}

void SolidFamily::add_energies(const FeModel&, ModelEnergies* energies) const {
  for (const auto& el : elements_) {
    energies->elastic += el->elastic_energy();
    energies->plastic += el->plastic_work();
  }
}

void SolidFamily::add_vtu_data(const FeModel&, mesh::VtuFrame* frame) const {
  mesh::VtuField eqps{"eqps", 1, {}}, thickness{"thickness", 1, {}};
  mesh::VtuField s11{"stress_11", 1, {}}, s22{"stress_22", 1, {}}, s33{"stress_33", 1, {}}, hourglass{"hourglass_work", 1, {}};
  for (int e = 0; e < num_elements(); ++e) {
    const element::SolidElement& el = element(e);
    if (kind_ == SolidElementKind::brick) hourglass.values.push_back(brick(e).hourglass_energy());
    const element::Voigt6 stress = el.mean_stress();
    eqps.values.push_back(el.max_eqps());
    thickness.values.push_back(element_thickness(e));
    s11.values.push_back(stress(0));
    s22.values.push_back(stress(1));
    s33.values.push_back(stress(2));
  }
  for (auto* f : {&eqps, &thickness, &s11, &s22, &s33}) frame->cell_data.push_back(std::move(*f));
  if (kind_ == SolidElementKind::brick) frame->cell_data.push_back(std::move(hourglass));
}

MidSurface SolidFamily::mid_surface(const FeModel& model) const {
  const std::size_t levels = static_cast<std::size_t>(layers_) + 1, nn = model.mesh().nodes.size(), n = nn / levels;
  if (n * levels != nn) throw std::logic_error(name() + " family: the mesh's nodes are not " + std::to_string(levels) + " levels of a sheet");
  MidSurface m;
  const std::vector<Eigen::Vector3d>& X = model.mesh().nodes;
  const std::vector<Eigen::Vector3d>& x = model.positions();
  const std::size_t top = static_cast<std::size_t>(layers_) * n;
  for (std::size_t i = 0; i < n; ++i) {
    m.reference.push_back(0.5 * (X[i] + X[top + i]));
    m.current.push_back(0.5 * (x[i] + x[top + i]));
    const Eigen::Vector3d across = x[top + i] - x[i];
    m.thickness.push_back(across.norm());
    m.director.push_back(across / across.norm());
  }
  return m;
}

MidSurfaceSensitivity SolidFamily::mid_surface_sensitivity(const FeModel& model) const {
  const std::size_t levels = static_cast<std::size_t>(layers_) + 1, n = model.mesh().nodes.size() / levels;
  const std::size_t top = static_cast<std::size_t>(layers_) * n;
  const std::vector<Eigen::Vector3d>& x = model.positions();
  MidSurfaceSensitivity m;
  m.thickness.resize(static_cast<Eigen::Index>(n), model.sensitivity_count());
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Matrix<double, 3, Eigen::Dynamic> db = model.position_sensitivity(static_cast<int>(i)),
                                                   dt = model.position_sensitivity(static_cast<int>(top + i));
    m.current.push_back(0.5 * (db + dt));
    const Eigen::Vector3d unit = (x[top + i] - x[i]).normalized();
    m.thickness.row(static_cast<Eigen::Index>(i)) = unit.transpose() * (dt - db);
  }
  return m;
}

void SolidFamily::save_state(io::BinaryWriter& w) const {
  w.i64(static_cast<std::int64_t>(elements_.size()));
  for (const auto& el : elements_) el->save_state(w);
}

void SolidFamily::load_state(io::BinaryReader& r) {
  r.expect_count((name() + " elements").c_str(), static_cast<std::int64_t>(elements_.size()));
  for (auto& el : elements_) el->load_state(r);
}

void SolidFamily::enable_sensitivities(const material::MaterialParams<material::SensitivityScalar>& law, int count) {
  sensitivity_count_ = count;
  material::ReturnMappingOptions o;
  o.single_jet_evaluation = true;  // the pseudo-load's pass; the update's asks for the tangent
  sensitivity_law_ = std::make_unique<element::SolidSensitivityLaw>(law, o, count);
  for (auto& el : elements_) el->enable_sensitivities(*sensitivity_law_, count);
}

bool SolidFamily::contribution_derivatives(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, const Eigen::MatrixXd* du,
                                           element::HexSensitivities* load, Eigen::Matrix<double, 3, material::kSensitivitySlots>* tool_force) const {
  tool_force->setZero();
  const int face = face_of_element_[static_cast<std::size_t>(e)];
  if (face < 0 || in.contributions.empty()) return false;
  // The top face's corners are the element's nodes 4-7, in the shell's p-variables (x_I, d_I)
  // with no director and no offset, as evaluate() passes them.
  const mesh::Hex& h = mesh_->hexes[static_cast<std::size_t>(e)];
  element::NodeVectors x, x0;
  const element::NodeVectors none{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  element::SensDofs dx = element::SensDofs::Zero();
  ElementContribution::ConfigurationDerivatives dc;
  for (int I = 0; I < 4; ++I) {
    x[static_cast<std::size_t>(I)] = in.x[static_cast<std::size_t>(h[static_cast<std::size_t>(I + 4)])];
    x0[static_cast<std::size_t>(I)] = in.x0[static_cast<std::size_t>(h[static_cast<std::size_t>(I + 4)])];
    dc.x0_d0.block(6 * I, 0, 3, material::kSensitivitySlots) = du0.block(3 * (I + 4), 0, 3, material::kSensitivitySlots);
    if (du) dx.block(6 * I, 0, 3, material::kSensitivitySlots) = du->block(3 * (I + 4), 0, 3, material::kSensitivitySlots);
  }
  if (du) dc.x_d = &dx;
  const ElementConfiguration config{x, none, x0, none, 0.0};
  element::SensDofs drp = element::SensDofs::Zero();
  bool touched = false;
  for (const auto& c : in.contributions) touched |= c->add_derivatives(face, config, dc, &drp, tool_force, du != nullptr);
  if (touched && load)
    for (int I = 0; I < 4; ++I) load->block(3 * (I + 4), 0, 3, material::kSensitivitySlots) += drp.block(6 * I, 0, 3, material::kSensitivitySlots);
  return touched;
}

solver::ElementEvaluation SolidFamily::sensitivity_load(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, Eigen::MatrixXd* load) {
  element::HexSensitivities l;
  const element::PointStatus s = elements_[static_cast<std::size_t>(e)]->sensitivities(corners(mesh_->hexes[static_cast<std::size_t>(e)], in.x), *sensitivity_law_, nullptr, &l);
  if (!s.ok) return {false, name() + " element " + std::to_string(e), s.reason, s.suggested_scale};
  Eigen::Matrix<double, 3, material::kSensitivitySlots> force;
  contribution_derivatives(e, in, du0, nullptr, &l, &force);
  *load = l;
  return {};
}

solver::ElementEvaluation SolidFamily::update_sensitivities(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, const Eigen::MatrixXd& du,
                                                            Eigen::Matrix<double, 3, material::kSensitivitySlots>* contribution_force) {
  const element::HexSensitivities dus = du;
  const element::PointStatus s = elements_[static_cast<std::size_t>(e)]->sensitivities(corners(mesh_->hexes[static_cast<std::size_t>(e)], in.x), *sensitivity_law_, &dus, nullptr);
  if (!s.ok) return {false, name() + " element " + std::to_string(e), s.reason, s.suggested_scale};
  // Every element with a top face, so that the contributions keep their trial derivatives.
  Eigen::Matrix<double, 3, material::kSensitivitySlots> force;
  contribution_derivatives(e, in, du0, &du, nullptr, &force);
  if (contribution_force) *contribution_force = force;
  return {};
}

bool SolidFamily::tangent_was_exact() const {
  for (const auto& el : elements_)
    if (!el->tangent_was_exact()) return false;
  return true;
}

void SolidFamily::set_exact_tangents(bool exact) {
  for (auto& el : elements_) el->set_exact_tangents(exact);
}

material::SensitivityRow SolidFamily::thickness_sensitivity(int e) const {
  const int per_layer = num_elements() / layers_;
  const int q = e % per_layer;
  material::SensitivityRow d = material::SensitivityRow::Zero();
  for (int l = 0; l < layers_; ++l) {
    const int k = l * per_layer + q;
    d += height0_[static_cast<std::size_t>(k)] * element(k).thickness_ratio_sensitivity();
  }
  return d;
}

void SolidFamily::save_sensitivities(io::BinaryWriter& w) const {
  for (const auto& el : elements_) el->save_sensitivities(w, sensitivity_count_);
}

void SolidFamily::load_sensitivities(io::BinaryReader& r) {
  for (auto& el : elements_) el->load_sensitivities(r, sensitivity_count_);
}

}  // namespace spifit::model
