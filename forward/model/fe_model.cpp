#include "forward/model/fe_model.hpp"

#include "forward/element/director.hpp"
#include "forward/io/binary_archive.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace spifit::model {

FeModel::FeModel(const mesh::Mesh& mesh, std::unique_ptr<ElementFamily> family) : mesh_(&mesh), family_(std::move(family)) {
  if (!family_) throw std::invalid_argument("FE model without an element family");
  const int nn = mesh.num_nodes(), ne = family_->num_elements();
  // Every node takes the layout of the family's elements.
  node_dofs_.assign(static_cast<std::size_t>(nn), family_->dofs_per_node());
  dof_offset_.resize(static_cast<std::size_t>(nn));
  for (int n = 0; n < nn; ++n) {
    dof_offset_[static_cast<std::size_t>(n)] = num_dofs_;
    for (int c = 0; c < node_dofs(n); ++c) dof_node_.push_back(n);
    num_dofs_ += node_dofs(n);
  }
  element_nodes_.resize(static_cast<std::size_t>(ne));
  element_dofs_.resize(static_cast<std::size_t>(ne));
  for (int e = 0; e < ne; ++e) {
    auto& nodes = element_nodes_[static_cast<std::size_t>(e)];
    nodes = family_->element_nodes(e);
    auto& dofs = element_dofs_[static_cast<std::size_t>(e)];
    for (int node : nodes)
      for (int c = 0; c < node_dofs(node); ++c) dofs.push_back(node_dof(node, c));
  }
  d0_ = family_->reference_directors();
  if (d0_.empty()) d0_.assign(static_cast<std::size_t>(nn), Eigen::Vector3d::Zero());
  x_ = xi_ = xt_ = mesh.nodes;
  d_ = di_ = dt_ = d0_;
  increment_ = increment_trial_ = Eigen::VectorXd::Zero(num_dofs());
}

void FeModel::add_nodal_load(int dof_index, double amplitude) {
  if (dof_index < 0 || dof_index >= num_dofs()) throw std::invalid_argument("load on DOF " + std::to_string(dof_index) + " out of range");
  // The shell carries no moment about its director (the drilling rotation has no stiffness).
  const int node = dof_node_[static_cast<std::size_t>(dof_index)], comp = dof_index - node_dof(node, 0);
  if (comp >= 3 && amplitude != 0.0 && std::abs(d0_[static_cast<std::size_t>(node)](comp - 3)) > 1e-8)
    throw std::invalid_argument("moment about axis " + std::to_string(comp - 3) + " at node " + std::to_string(node) +
                                " has a component about the shell normal (drilling), which the shell cannot carry");
  loads_.emplace_back(dof_index, amplitude);
}

Eigen::VectorXd FeModel::internal_forces() {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(num_dofs());
  Eigen::VectorXd re;
  for (int e = 0; e < num_elements(); ++e) {
    const solver::ElementEvaluation ev = evaluate_element(e, &re, nullptr);
    if (!ev.ok) throw std::runtime_error("internal forces: " + ev.where + ": " + ev.reason);
    const auto& dofs = element_dofs_[static_cast<std::size_t>(e)];
    for (std::size_t a = 0; a < dofs.size(); ++a) f(dofs[a]) += re(static_cast<Eigen::Index>(a));
  }
  frames_.rotate(dt_, false, &f);  // evaluate_element works in the frames of the trial directors
  return f;
}

int FeModel::use_nodal_rotation_frames(solver::DofConstraints* c) {
  if (c->num_dofs() != num_dofs())
    throw std::invalid_argument("nodal rotation frames: constraints of " + std::to_string(c->num_dofs()) + " DOFs for a model of " +
                                std::to_string(num_dofs()));
  for (int n = 0; n < num_nodes(); ++n)
    if (node_dofs(n) != 6)
      throw std::invalid_argument("nodal rotation frames: node " + std::to_string(n) + " of the " + family_->name() + " elements has no rotations");
  frames_ = NodalRotationFrames(d0_, c);
  return frames_.count();
}

std::string FeModel::describe_dof(int dof) const {
  if (dof < 0 || dof >= num_dofs()) return "DOF " + std::to_string(dof);
  const int node = dof_node_[static_cast<std::size_t>(dof)], k = dof - node_dof(node, 0);
  const Eigen::Vector3d& p = x_[static_cast<std::size_t>(node)];
  char buf[160];
  if (k >= 3 && has_rotation_frame(node)) {
    static const char* const axis[3] = {"t1", "t2", "normal"};
    std::snprintf(buf, sizeof buf, "node %d (%.4g, %.4g, %.4g) rotation %s (nodal frame)", node, p.x(), p.y(), p.z(), axis[k - 3]);
    return buf;
  }
  std::snprintf(buf, sizeof buf, "node %d (%.4g, %.4g, %.4g) %s %c", node, p.x(), p.y(), p.z(), k < 3 ? "displacement" : "rotation",
                "xyz"[k % 3]);
  return buf;
}

void FeModel::begin_increment(double lambda0, double lambda1) {
  for (auto& c : contributions_) c->begin_increment(lambda0, lambda1);
}

solver::ElementEvaluation FeModel::evaluate_element(int e, Eigen::VectorXd* re, Eigen::MatrixXd* ke) {
  const ElementInputs in{xt_, dt_, x_, d_, contributions_, frames_};
  return family_->evaluate(e, in, re, ke);
}

Eigen::VectorXd FeModel::external_forces(double lambda) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(num_dofs());
  for (const auto& [i, a] : loads_) f(i) += lambda * a;
  frames_.rotate(dt_, true, &f);  // moments at framed nodes, as the element forces they balance
  return f;
}

void FeModel::set_trial(const Eigen::VectorXd& delta, double alpha) {
  // Rotations of framed nodes come in the frames of the iterate's directors (those of the
  // tangent they were solved with).
  Eigen::VectorXd step = alpha * delta;
  frames_.rotate(di_, false, &step);
  for (std::size_t n = 0; n < x_.size(); ++n) {
    const Eigen::Index o = dof_offset_[n];
    xt_[n] = xi_[n] + step.segment<3>(o);
    if (node_dofs_[n] == 6) dt_[n] = element::rotate_by_vector(di_[n], step.segment<3>(o + 3));
  }
  increment_trial_ = increment_ + step;
}

void FeModel::accept_trial() {
  xi_ = xt_;
  di_ = dt_;
  increment_ = increment_trial_;
}

void FeModel::commit(double lambda) {
  // External work of the nodal loads over the increment of their DOF (trapezoidal rule).
  for (const auto& [i, a] : loads_) load_work_ += 0.5 * (lambda_ + lambda) * a * increment_(i);
  for (auto& c : contributions_) c->before_commit(*this);
  // The last evaluation was at the accepted iterate: its element trial states are the ones to keep.
  x_ = xi_;
  d_ = di_;
  family_->commit();
  force_sensitivity_ = force_sensitivity_trial_;
  position_sensitivity_ = position_sensitivity_trial_;
  for (auto& c : contributions_) c->after_commit(*this);
  increment_.setZero();
  increment_trial_.setZero();
  lambda_ = lambda;
}

void FeModel::revert() {
  xi_ = xt_ = x_;
  di_ = dt_ = d_;
  family_->revert();
  for (auto& c : contributions_) c->revert();
  increment_.setZero();
  increment_trial_.setZero();
}

Eigen::VectorXd FeModel::increment_from_committed() const {
  Eigen::VectorXd v = increment_;  // x, y, z
  frames_.rotate(di_, true, &v);
  return v;
}

void FeModel::restore_committed(double lambda, std::vector<Eigen::Vector3d> x, std::vector<Eigen::Vector3d> d, double load_work) {
  lambda_ = lambda;
  x_ = std::move(x);
  d_ = std::move(d);
  load_work_ = load_work;
  revert();  // iterate and trial = committed
}

std::vector<double> FeModel::nodal_thickness() const {
  std::vector<double> h(x_.size(), 0.0), w(x_.size(), 0.0);
  for (int e = 0; e < num_elements(); ++e) {
    const double he = element_thickness(e);
    for (int i : element_nodes_[static_cast<std::size_t>(e)]) {
      h[static_cast<std::size_t>(i)] += he;
      w[static_cast<std::size_t>(i)] += 1.0;
    }
  }
  for (std::size_t i = 0; i < h.size(); ++i) h[i] /= w[i];
  return h;
}

Eigen::MatrixXd FeModel::nodal_thickness_sensitivity() const {
  Eigen::MatrixXd dh = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(x_.size()), sensitivity_count_);
  if (sensitivity_count_ == 0) return dh;
  Eigen::VectorXd w = Eigen::VectorXd::Zero(dh.rows());
  for (int e = 0; e < num_elements(); ++e) {  // as nodal_thickness, in element order
    const Eigen::RowVectorXd de = family_->thickness_sensitivity(e).head(sensitivity_count_);
    for (int i : element_nodes_[static_cast<std::size_t>(e)]) {
      dh.row(i) += de;
      w(i) += 1.0;
    }
  }
  for (Eigen::Index i = 0; i < dh.rows(); ++i) dh.row(i) /= w(i);
  return dh;
}

void FeModel::save_sensitivities(io::BinaryWriter& w) const {
  w.i64(sensitivity_count_);
  w.matrix(position_sensitivity_);
  w.matrix(force_sensitivity_);
  family_->save_sensitivities(w);
  for (const auto& c : contributions_) c->save_sensitivities(w, sensitivity_count_);
}

void FeModel::load_sensitivities(io::BinaryReader& r) {
  r.expect_count("parameters with sensitivities", sensitivity_count_);
  Eigen::MatrixXd du = r.matrix(), force = r.matrix();
  if (du.rows() != num_dofs_ || du.cols() != sensitivity_count_ || force.rows() != 3 || force.cols() != sensitivity_count_)
    throw io::ArchiveError("the DOFs' or the force's derivatives of another size");
  position_sensitivity_ = position_sensitivity_trial_ = std::move(du);
  force_sensitivity_ = force_sensitivity_trial_ = force;
  family_->load_sensitivities(r);
  for (const auto& c : contributions_) c->load_sensitivities(r, sensitivity_count_);
}

void ElementFamily::save_sensitivities(io::BinaryWriter& w) const {
  (void)w;
  throw std::logic_error(name() + " elements have no sensitivities to save");
}

void ElementFamily::load_sensitivities(io::BinaryReader& r) {
  (void)r;
  throw std::logic_error(name() + " elements have no sensitivities to load");
}

material::SensitivityRow ElementFamily::thickness_sensitivity(int e) const {
  (void)e;
  throw std::logic_error(name() + " elements have no thickness sensitivities");
}

void ElementFamily::enable_sensitivities(const material::MaterialParams<material::SensitivityScalar>& law, int count) {
  (void)law, (void)count;
  throw std::invalid_argument(name() + " elements have no parameter sensitivities yet");
}

solver::ElementEvaluation ElementFamily::sensitivity_load(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, Eigen::MatrixXd* load) {
  (void)e; (void)in; (void)du0; (void)load;
  return {false, name() + " elements", "no parameter sensitivities", 1.0};
}

solver::ElementEvaluation ElementFamily::update_sensitivities(int e, const ElementInputs& in, const Eigen::MatrixXd& du0, const Eigen::MatrixXd& du,
                                                              Eigen::Matrix<double, 3, material::kSensitivitySlots>* contribution_force) {
  (void)e; (void)in; (void)du0; (void)du; (void)contribution_force;
  return {false, name() + " elements", "no parameter sensitivities", 1.0};
}

void FeModel::enable_sensitivities(const std::vector<material::FieldSeed>& seeds, int count, const material::MaterialParams<double>& material) {
  if (count < 1 || count > material::kSensitivitySlots)
    throw std::invalid_argument("sensitivities: " + std::to_string(count) + " parameters; a run differentiates 1 to " +
                                std::to_string(material::kSensitivitySlots));
  for (const auto& c : contributions_) {
    const std::string why = c->sensitivity_refusal();
    if (!why.empty()) throw std::invalid_argument("sensitivities: " + why);
  }
  family_->enable_sensitivities(material::seeded_params(material, seeds), count);
  for (const auto& c : contributions_) c->enable_sensitivities();
  sensitivity_count_ = count;
  force_sensitivity_ = force_sensitivity_trial_ = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, count);
  position_sensitivity_ = position_sensitivity_trial_ = Eigen::MatrixXd::Zero(num_dofs_, count);
}

Eigen::MatrixXd FeModel::element_sensitivity(const Eigen::MatrixXd& global, int e) const {
  const std::vector<int>& dofs = element_dofs_[static_cast<std::size_t>(e)];
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(dofs.size()), material::kSensitivitySlots);
  for (std::size_t a = 0; a < dofs.size(); ++a) out.row(static_cast<Eigen::Index>(a)).head(global.cols()) = global.row(dofs[a]);
  return out;
}

solver::ElementEvaluation FeModel::sensitivity_load(Eigen::MatrixXd* load) {
  const ElementInputs in{xt_, dt_, x_, d_, contributions_, frames_};
  const int ne = num_elements();
  std::vector<Eigen::MatrixXd> le(static_cast<std::size_t>(ne));
  std::vector<solver::ElementEvaluation> ev(static_cast<std::size_t>(ne));
#pragma omp parallel for schedule(dynamic, 16)
  for (int e = 0; e < ne; ++e)
    ev[static_cast<std::size_t>(e)] = family_->sensitivity_load(e, in, element_sensitivity(position_sensitivity_, e), &le[static_cast<std::size_t>(e)]);
  *load = Eigen::MatrixXd::Zero(num_dofs_, sensitivity_count_);
  for (int e = 0; e < ne; ++e) {  // in element order: the sums do not depend on the threads
    const auto ue = static_cast<std::size_t>(e);
    if (!ev[ue].ok) return ev[ue];
    const std::vector<int>& dofs = element_dofs_[ue];
    for (std::size_t a = 0; a < dofs.size(); ++a) load->row(dofs[a]) += le[ue].row(static_cast<Eigen::Index>(a)).head(sensitivity_count_);
  }
  for (int k = 0; k < sensitivity_count_; ++k) {  // moments at framed nodes in their frames, as the residual's
    Eigen::VectorXd col = load->col(k);
    frames_.rotate(dt_, true, &col);
    load->col(k) = col;
  }
  return {};
}

solver::ElementEvaluation FeModel::update_sensitivities(const Eigen::MatrixXd& du) {
  Eigen::MatrixXd global = du;  // rotations of framed nodes about x, y, z
  for (Eigen::Index k = 0; k < du.cols(); ++k) {
    Eigen::VectorXd col = du.col(k);
    frames_.rotate(dt_, false, &col);
    global.col(k) = col;
  }
  const ElementInputs in{xt_, dt_, x_, d_, contributions_, frames_};
  const int ne = num_elements();
  using Force = Eigen::Matrix<double, 3, material::kSensitivitySlots>;
  std::vector<Force> fe(static_cast<std::size_t>(ne), Force::Zero());
  std::vector<solver::ElementEvaluation> ev(static_cast<std::size_t>(ne));
#pragma omp parallel for schedule(dynamic, 16)
  for (int e = 0; e < ne; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    ev[ue] = family_->update_sensitivities(e, in, element_sensitivity(position_sensitivity_, e), element_sensitivity(global, e), &fe[ue]);
  }
  position_sensitivity_trial_ = global;
  force_sensitivity_trial_.setZero();
  for (int e = 0; e < ne; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (!ev[ue].ok) return ev[ue];
    force_sensitivity_trial_ += fe[ue].leftCols(sensitivity_count_);
  }
  return {};
}

MidSurface ElementFamily::mid_surface(const FeModel& model) const {
  MidSurface m;
  m.reference = model.mesh().nodes;
  m.current = model.positions();
  m.director = model.directors();
  m.thickness = model.nodal_thickness();
  return m;
}

MidSurfaceSensitivity ElementFamily::mid_surface_sensitivity(const FeModel& model) const {
  MidSurfaceSensitivity m;
  const int nodes = static_cast<int>(model.positions().size());
  m.current.reserve(static_cast<std::size_t>(nodes));
  for (int i = 0; i < nodes; ++i) m.current.push_back(model.position_sensitivity(i));
  m.thickness = model.nodal_thickness_sensitivity();
  return m;
}

}  // namespace spifit::model
