#include "forward/model/shell_model.hpp"

#include "forward/element/director.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace spifit::model {

namespace {
// The four corners' positions and directors of element quad q, taken from node vectors xs, ds.
void corner_vectors(const mesh::Quad& q, const std::vector<Eigen::Vector3d>& xs, const std::vector<Eigen::Vector3d>& ds,
                    element::NodeVectors* x, element::NodeVectors* d) {
  for (std::size_t i = 0; i < 4; ++i) {
    (*x)[i] = xs[static_cast<std::size_t>(q[i])];
    (*d)[i] = ds[static_cast<std::size_t>(q[i])];
  }
}

// The axis a = (a_r, a_theta, a_z) read in the polar frame (e_r, e_theta, z) at the centroid of
// the corners X (ShellModelOptions::material_axes = polar); a itself at a centroid on the z axis.
Eigen::Vector3d polar_axis(const element::NodeVectors& X, const Eigen::Vector3d& a) {
  const Eigen::Vector3d c = 0.25 * (X[0] + X[1] + X[2] + X[3]);
  const double r = std::hypot(c.x(), c.y());
  if (!(r > 1e-12 * (1.0 + c.norm()))) return a;
  const Eigen::Vector3d er(c.x() / r, c.y() / r, 0.0), et(-er.y(), er.x(), 0.0);
  return a.x() * er + a.y() * et + a.z() * Eigen::Vector3d::UnitZ();
}
}  // namespace

bool material_axes_from_string(const std::string& s, ShellModelOptions::MaterialAxes* axes) {
  if (s == "fixed") { *axes = ShellModelOptions::MaterialAxes::fixed; return true; }
  if (s == "polar") { *axes = ShellModelOptions::MaterialAxes::polar; return true; }
  return false;
}

const char* to_string(ShellModelOptions::MaterialAxes axes) { return axes == ShellModelOptions::MaterialAxes::polar ? "polar" : "fixed"; }

ShellModel::ShellModel(const mesh::Mesh& mesh, double thickness, const material::MaterialParams<double>& material,
                       const ShellModelOptions& options)
    : mesh_(&mesh), options_(options), law_(material), rule_(element::make_thickness_rule(options.shell.thickness_rule, options.shell.thickness_points)),
      thickness_(thickness) {
  if (!(thickness > 0.0)) throw std::invalid_argument("thickness must be > 0, got " + std::to_string(thickness));
  check_geometry(mesh, thickness);
  build_directors_and_elements(mesh, thickness);
  x_ = xi_ = xt_ = mesh.nodes;
  d_ = di_ = dt_ = d0_;
  increment_ = increment_trial_ = Eigen::VectorXd::Zero(num_dofs());
}

// Node references in range, and the thickness over the shortest edge of each element against
// the limits of the options.
void ShellModel::check_geometry(const mesh::Mesh& mesh, double thickness) {
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
// diagonal cross product, which weights by area); then the elements and their DOFs.
void ShellModel::build_directors_and_elements(const mesh::Mesh& mesh, double thickness) {
  const int nn = mesh.num_nodes(), ne = mesh.num_elements();
  d0_.assign(static_cast<std::size_t>(nn), Eigen::Vector3d::Zero());
  for (int e = 0; e < ne; ++e) {
    const auto& q = mesh.quads[static_cast<std::size_t>(e)];
    const auto& p = mesh.nodes;
    const Eigen::Vector3d n = (p[static_cast<std::size_t>(q[2])] - p[static_cast<std::size_t>(q[0])])
                                  .cross(p[static_cast<std::size_t>(q[3])] - p[static_cast<std::size_t>(q[1])]);
    for (int i : q) d0_[static_cast<std::size_t>(i)] += n;
  }
  for (int i = 0; i < nn; ++i) {
    const double len = d0_[static_cast<std::size_t>(i)].norm();
    if (!(len > 0.0)) throw std::invalid_argument("node " + std::to_string(i) +
                                  ": the normals of its elements cancel (no element, degenerate elements or inconsistent orientation)");
    d0_[static_cast<std::size_t>(i)] /= len;
  }
  elements_.reserve(static_cast<std::size_t>(ne));
  element_dofs_.resize(static_cast<std::size_t>(ne));
  for (int e = 0; e < ne; ++e) {
    const auto& q = mesh.quads[static_cast<std::size_t>(e)];
    element::NodeVectors X, D;
    corner_vectors(q, mesh.nodes, d0_, &X, &D);
    element::ShellOptions shell = options_.shell;
    if (options_.material_axes == ShellModelOptions::MaterialAxes::polar) shell.material_axis = polar_axis(X, options_.shell.material_axis);
    try {
      elements_.emplace_back(X, D, thickness, law_, rule_, shell);
    } catch (const std::invalid_argument& err) {
      throw std::invalid_argument("element " + std::to_string(e) + ": " + err.what());
    }
    auto& dofs = element_dofs_[static_cast<std::size_t>(e)];
    for (int node : q)
      for (int c = 0; c < 6; ++c) dofs.push_back(dof(node, c));
  }
}

void ShellModel::add_nodal_load(int dof_index, double amplitude) {
  if (dof_index < 0 || dof_index >= num_dofs()) throw std::invalid_argument("load on DOF " + std::to_string(dof_index) + " out of range");
  // The shell carries no moment about its director (the drilling rotation has no stiffness).
  const int node = dof_index / 6, comp = dof_index % 6;
  if (comp >= 3 && amplitude != 0.0 && std::abs(d0_[static_cast<std::size_t>(node)](comp - 3)) > 1e-8)
    throw std::invalid_argument("moment about axis " + std::to_string(comp - 3) + " at node " + std::to_string(node) +
                                " has a component about the shell normal (drilling), which the shell cannot carry");
  loads_.emplace_back(dof_index, amplitude);
}

void ShellModel::add_surface_load(const std::vector<int>& elements, const Eigen::Vector3d& load_per_area) {
  const double g = 1.0 / std::sqrt(3.0);
  for (int e : elements) {
    const auto& q = mesh_->quads.at(static_cast<std::size_t>(e));
    element::NodeVectors X;
    for (std::size_t i = 0; i < 4; ++i) X[i] = mesh_->nodes[static_cast<std::size_t>(q[i])];
    for (int p = 0; p < 4; ++p) {
      const double xi = element::kNodeXi[p] * g, eta = element::kNodeEta[p] * g;
      const Eigen::Vector4d n = element::quad_shape(xi, eta);
      const double da = element::quad_area_jacobian(X, xi, eta);
      for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c)
          if (load_per_area(c) != 0.0) loads_.emplace_back(dof(q[static_cast<std::size_t>(i)], c), n(i) * da * load_per_area(c));
    }
  }
}

Eigen::VectorXd ShellModel::internal_forces() {
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

int ShellModel::use_nodal_rotation_frames(solver::DofConstraints* c) {
  if (c->num_dofs() != num_dofs())
    throw std::invalid_argument("nodal rotation frames: constraints of " + std::to_string(c->num_dofs()) + " DOFs for a model of " +
                                std::to_string(num_dofs()));
  frames_ = NodalRotationFrames(d0_, c);
  return frames_.count();
}

std::string ShellModel::describe_dof(int dof) const {
  const int node = dof / 6, k = dof % 6;
  if (dof < 0 || node >= static_cast<int>(x_.size())) return "DOF " + std::to_string(dof);
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

void ShellModel::begin_increment(double lambda0, double lambda1) {
  for (auto& c : contributions_) c->begin_increment(lambda0, lambda1);
}

void ShellModel::committed_corners(int e, element::NodeVectors* x, element::NodeVectors* d) const {
  corner_vectors(mesh_->quads[static_cast<std::size_t>(e)], x_, d_, x, d);
}

double ShellModel::element_thickness(int e) const {
  const element::ShellQ4& el = elements_[static_cast<std::size_t>(e)];
  double h = 0.0;
  for (int p = 0; p < el.points(); ++p) h += el.section(p).thickness();
  return h / el.points();
}

solver::ElementEvaluation ShellModel::evaluate_element(int e, Eigen::VectorXd* re, Eigen::MatrixXd* ke) {
  const auto& q = mesh_->quads[static_cast<std::size_t>(e)];
  element::NodeVectors x, d;
  corner_vectors(q, xt_, dt_, &x, &d);
  element::Vec24 r;
  element::Mat24 k;
  const element::ElementStatus s = elements_[static_cast<std::size_t>(e)].compute(x, d, &r, ke ? &k : nullptr);
  solver::ElementEvaluation out;
  if (!s.ok) {
    out.ok = false;
    out.reason = s.reason;
    out.suggested_scale = s.suggested_scale;
    out.where = "element " + std::to_string(e);
    if (s.point >= 0) out.where += ", in-plane point " + std::to_string(s.point);
    if (s.layer >= 0) out.where += ", layer " + std::to_string(s.layer);
    return out;
  }
  if (!contributions_.empty()) {
    // The contributions add in the p-variables (positions and directors), turned into nodal
    // forces and moments once.
    element::Vec24 rc = element::Vec24::Zero();
    element::Mat24 kc = element::Mat24::Zero();
    element::NodeVectors x0, d0;
    corner_vectors(q, x_, d_, &x0, &d0);
    const ElementConfiguration config{x, d, x0, d0, 0.5 * element_thickness(e)};
    bool touched = false;
    for (auto& c : contributions_) touched |= c->add(e, config, &rc, ke ? &kc : nullptr);
    if (touched) {
      element::Vec24 ru;
      element::Mat24 ku;
      element::director_to_dofs(d, rc, ke ? &kc : nullptr, &ru, ke ? &ku : nullptr);
      r += ru;
      if (ke) k += ku;
    }
  }
  if (!frames_.empty()) {
    // Rotation rows and columns of framed nodes into their frames at the trial directors.
    for (int I = 0; I < 4; ++I) {
      if (!frames_.framed(q[static_cast<std::size_t>(I)])) continue;
      const Eigen::Matrix3d f = frames_.frame(q[static_cast<std::size_t>(I)], d[static_cast<std::size_t>(I)]);
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

Eigen::VectorXd ShellModel::external_forces(double lambda) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(num_dofs());
  for (const auto& [i, a] : loads_) f(i) += lambda * a;
  frames_.rotate(dt_, true, &f);  // moments at framed nodes, as the element forces they balance
  return f;
}

void ShellModel::set_trial(const Eigen::VectorXd& delta, double alpha) {
  // Rotations of framed nodes come in the frames of the iterate's directors (those of the
  // tangent they were solved with).
  Eigen::VectorXd step = alpha * delta;
  frames_.rotate(di_, false, &step);
  for (std::size_t n = 0; n < x_.size(); ++n) {
    const Eigen::Index o = static_cast<Eigen::Index>(6 * n);
    xt_[n] = xi_[n] + step.segment<3>(o);
    dt_[n] = element::rotate_by_vector(di_[n], step.segment<3>(o + 3));
  }
  increment_trial_ = increment_ + step;
}

void ShellModel::accept_trial() {
  xi_ = xt_;
  di_ = dt_;
  increment_ = increment_trial_;
}

void ShellModel::commit(double lambda) {
  // External work of the nodal loads over the increment of their DOF (trapezoidal rule).
  for (const auto& [i, a] : loads_) load_work_ += 0.5 * (lambda_ + lambda) * a * increment_(i);
  for (auto& c : contributions_) c->before_commit(*this);
  // The last evaluation was at the accepted iterate: its element trial states are the ones to keep.
  x_ = xi_;
  d_ = di_;
  for (auto& el : elements_) el.commit();
  for (auto& c : contributions_) c->after_commit(*this);
  increment_.setZero();
  increment_trial_.setZero();
  lambda_ = lambda;
}

void ShellModel::revert() {
  xi_ = xt_ = x_;
  di_ = dt_ = d_;
  for (auto& el : elements_) el.revert();
  for (auto& c : contributions_) c->revert();
  increment_.setZero();
  increment_trial_.setZero();
}

Eigen::VectorXd ShellModel::increment_from_committed() const {
  Eigen::VectorXd v = increment_;  // x, y, z
  frames_.rotate(di_, true, &v);
  return v;
}

void ShellModel::restore_committed(double lambda, std::vector<Eigen::Vector3d> x, std::vector<Eigen::Vector3d> d, double load_work) {
  lambda_ = lambda;
  x_ = std::move(x);
  d_ = std::move(d);
  load_work_ = load_work;
  revert();  // iterate and trial = committed
}

std::vector<double> ShellModel::nodal_thickness() const {
  std::vector<double> h(x_.size(), 0.0), w(x_.size(), 0.0);
  for (int e = 0; e < num_elements(); ++e) {
    const double he = element_thickness(e);
    for (int i : mesh_->quads[static_cast<std::size_t>(e)]) {
      h[static_cast<std::size_t>(i)] += he;
      w[static_cast<std::size_t>(i)] += 1.0;
    }
  }
  for (std::size_t i = 0; i < h.size(); ++i) h[i] /= w[i];
  return h;
}

}  // namespace spifit::model
