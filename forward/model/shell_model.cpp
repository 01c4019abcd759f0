#include "forward/model/shell_model.hpp"

#include "forward/element/director.hpp"
#include "forward/io/binary_archive.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
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

// A unit vector normal to the unit vector d: the global axis least aligned with d, made normal
// to it (x for d = +-z).
Eigen::Vector3d least_aligned_normal(const Eigen::Vector3d& d) {
  Eigen::Index k = 0;
  d.cwiseAbs().minCoeff(&k);
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(k);
  return (e - e.dot(d) * d).normalized();
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
  const int nn = mesh.num_nodes(), ne = mesh.num_elements();
  if (ne == 0) throw std::invalid_argument("the mesh has no element");
  for (int e = 0; e < ne; ++e)
    for (int i : mesh.quads[static_cast<std::size_t>(e)])
      if (i < 0 || i >= nn) throw std::invalid_argument("element " + std::to_string(e) + " refers to node " + std::to_string(i) + " out of range");
  // Thickness over the shortest edge of each element.
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
  if (max_t_over_l_ > options.max_thickness_over_length) {
    std::snprintf(buf, sizeof buf, "thickness over element length t/l = %.3g at element %d exceeds %.3g: refine less or use a solid-shell",
                  max_t_over_l_, worst, options.max_thickness_over_length);
    throw std::invalid_argument(buf);
  }
  if (max_t_over_l_ > options.warn_thickness_over_length) {
    std::snprintf(buf, sizeof buf, "t/l = %.3g at element %d is above %.3g: transverse shear and thickness stress matter there (the thesis's fine cone mesh has 1.7)",
                  max_t_over_l_, worst, options.warn_thickness_over_length);
    warnings_.emplace_back(buf);
  }
  // Nodal directors: normalised sum of the normals of the elements around each node (the
  // diagonal cross product, which weights by area).
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
    for (int i = 0; i < 4; ++i) {
      X[static_cast<std::size_t>(i)] = mesh.nodes[static_cast<std::size_t>(q[static_cast<std::size_t>(i)])];
      D[static_cast<std::size_t>(i)] = d0_[static_cast<std::size_t>(q[static_cast<std::size_t>(i)])];
    }
    element::ShellOptions shell = options.shell;
    if (options.material_axes == ShellModelOptions::MaterialAxes::polar) shell.material_axis = polar_axis(X, options.shell.material_axis);
    try {
      elements_.emplace_back(X, D, thickness, law_, rule_, shell);
    } catch (const std::invalid_argument& err) {
      throw std::invalid_argument("element " + std::to_string(e) + ": " + err.what());
    }
    auto& dofs = element_dofs_[static_cast<std::size_t>(e)];
    for (int node : q)
      for (int c = 0; c < 6; ++c) dofs.push_back(dof(node, c));
  }
  x_ = xi_ = xt_ = mesh.nodes;
  d_ = di_ = dt_ = d0_;
  increment_ = increment_trial_ = Eigen::VectorXd::Zero(num_dofs());
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
  rotate_to_frames(dt_, false, &f);  // evaluate_element works in the frames of the trial directors
  return f;
}

int ShellModel::use_nodal_rotation_frames(solver::DofConstraints* c) {
  if (c->num_dofs() != num_dofs())
    throw std::invalid_argument("nodal rotation frames: constraints of " + std::to_string(c->num_dofs()) + " DOFs for a model of " +
                                std::to_string(num_dofs()));
  if (c->finalized()) throw std::logic_error("nodal rotation frames: call before DofConstraints::finalize()");
  const std::vector<char> master = c->master_flags();
  const auto nn = static_cast<std::size_t>(num_nodes());
  framed_.assign(nn, 0);
  frame_t1_.assign(nn, Eigen::Vector3d::Zero());
  int count = 0;
  for (int n = 0; n < num_nodes(); ++n) {
    bool free = true;
    for (int k = 3; k < 6; ++k) {
      const int i = dof(n, k);
      free = free && !c->prescribed(i) && !c->tied(i) && !master[static_cast<std::size_t>(i)];
    }
    if (!free) continue;
    // Reference frame: x, y, z itself for a flat sheet in the xy plane.
    frame_t1_[static_cast<std::size_t>(n)] = least_aligned_normal(d0_[static_cast<std::size_t>(n)]);
    framed_[static_cast<std::size_t>(n)] = 1;
    c->prescribe(dof(n, 5), 0.0);
    ++count;
  }
  return count;
}

// The frame is carried from the reference director a to d by the shortest rotation (axis
// a x d), R t = t + v x t + v x (v x t) / (1 + c) with v = a x d, c = a . d: smooth in d, so
// nearby directors have nearby frames. Beyond 150 deg of turn (never met in forming) any
// tangent will do: the frames are rebuilt from the directors at every use and nothing is
// carried in them from one configuration to another except the predictor, which is stored
// and used at the same directors.
Eigen::Matrix3d ShellModel::rotation_frame(int node, const Eigen::Vector3d& d) const {
  const auto n = static_cast<std::size_t>(node);
  const Eigen::Vector3d& a = d0_[n];
  const double c = a.dot(d);
  Eigen::Vector3d t1;
  if (c > -0.866) {
    const Eigen::Vector3d& t = frame_t1_[n];
    const Eigen::Vector3d v = a.cross(d);
    t1 = t + v.cross(t) + v.cross(v.cross(t)) / (1.0 + c);
    t1 = (t1 - t1.dot(d) * d).normalized();
  } else {
    t1 = least_aligned_normal(d);
  }
  Eigen::Matrix3d q;
  q.col(0) = t1;
  q.col(1) = d.cross(t1);
  q.col(2) = d;  // exactly the director the element uses: its drilling column is exactly decoupled
  return q;
}

void ShellModel::rotate_to_frames(const std::vector<Eigen::Vector3d>& ds, bool to_frame, Eigen::VectorXd* v) const {
  for (std::size_t n = 0; n < framed_.size(); ++n) {
    if (!framed_[n]) continue;
    auto seg = v->segment<3>(static_cast<Eigen::Index>(6 * n + 3));
    if (seg.isZero(0.0)) continue;
    const Eigen::Matrix3d q = rotation_frame(static_cast<int>(n), ds[n]);
    const Eigen::Vector3d w = seg;
    if (to_frame) seg.noalias() = q.transpose() * w;
    else seg.noalias() = q * w;
  }
}

void ShellModel::set_tool(double radius, ToolPathFunction path, const contact::ContactOptions& options, double spin_per_load_factor) {
  if (!(radius > 0.0)) throw std::invalid_argument("tool radius must be > 0");
  if (!std::isfinite(spin_per_load_factor)) throw std::invalid_argument("tool spin must be finite");
  spin_per_load_factor_ = spin_per_load_factor;
  if (const std::string err = options.validate(); !err.empty()) throw std::invalid_argument("contact: " + err);
  contact_ = std::make_unique<contact::ShellContact>(*mesh_, options, 1 + static_cast<int>(copies_deg_.size()));
  tool_path_ = std::move(path);
  tools_.assign(1 + copies_deg_.size(), contact::SphereTool{});
  for (auto& t : tools_) t.radius = radius;
  const Eigen::Vector3d c = tool_path_(lambda_);
  place_tools(c, c, Eigen::Vector3d::Zero());
}

void ShellModel::set_tool_copies(const std::vector<double>& angles_deg) {
  if (!contact_) throw std::logic_error("set_tool_copies: no tool (call set_tool first)");
  for (double a : angles_deg)
    if (!std::isfinite(a) || std::abs(std::remainder(a, 360.0)) < 1e-9)
      throw std::invalid_argument("tool copy angle " + std::to_string(a) + " deg: must be finite and not a multiple of 360");
  copies_deg_ = angles_deg;
  copy_rotations_.assign(1, Eigen::Matrix3d::Identity());
  for (double a : angles_deg)
    copy_rotations_.push_back(Eigen::AngleAxisd(a * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix());
  contact_ = std::make_unique<contact::ShellContact>(*mesh_, contact_->options(), 1 + static_cast<int>(angles_deg.size()));
  const contact::SphereTool real = tools_.front();
  tools_.assign(1 + angles_deg.size(), real);
  place_tools(real.centre_committed, real.centre, real.spin);
}

void ShellModel::place_tools(const Eigen::Vector3d& centre_committed, const Eigen::Vector3d& centre, const Eigen::Vector3d& spin) {
  for (std::size_t i = 0; i < tools_.size(); ++i) {
    const Eigen::Matrix3d& R = copy_rotations_[i];
    tools_[i].centre_committed = R * centre_committed;
    tools_[i].centre = R * centre;
    tools_[i].spin = R * spin;  // a spin about z is unchanged; any axis turns with the copy
  }
}

contact::ContactSummary ShellModel::contact_summary_of_tool(int i) const {
  if (!contact_) return {};
  return contact_->committed_summary(i);
}

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
contact::ContactSummary ShellModel::contact_summary() const {
  contact::ContactSummary out;
  if (!contact_) return out;
  for (int i = 0; i < contact_->tools(); ++i) {
    const contact::ContactSummary s = contact_->committed_summary(i);
    out.force_on_sheet += copy_rotations_[static_cast<std::size_t>(i)].transpose() * s.force_on_sheet;
    out.max_penetration = std::max(out.max_penetration, s.max_penetration);
    out.max_pressure = std::max(out.max_pressure, s.max_pressure);
    out.active_points += s.active_points;
  }
  return out;
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

double ShellModel::surface_penetration() const {
  if (!contact_) return 0.0;
  double deepest = contact_summary().max_penetration;
  for (int e = 0; e < mesh_->num_elements(); ++e) {
    const auto& q = mesh_->quads[static_cast<std::size_t>(e)];
    element::NodeVectors x, d;
    corner_vectors(q, x_, d_, &x, &d);
    const double offset = 0.5 * element_thickness(e);
    for (const contact::SphereTool& tool : tools_)
      deepest = std::max(deepest, contact::ShellContact::surface_penetration(contact_->options(), x, d, offset, tool));
  }
  return deepest;
}

void ShellModel::begin_increment(double lambda0, double lambda1) {
  if (!contact_) return;
  place_tools(tool_path_(lambda0), tool_path_(lambda1), Eigen::Vector3d(0.0, 0.0, spin_per_load_factor_ * (lambda1 - lambda0)));
}

double ShellModel::element_thickness(int e) const {
  double h = 0.0;
  for (int p = 0; p < element::ShellQ4::kPoints; ++p) h += 0.25 * elements_[static_cast<std::size_t>(e)].section(p).thickness();
  return h;
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
  if (contact_) {
    element::Vec24 rc = element::Vec24::Zero();
    element::Mat24 kc = element::Mat24::Zero();
    element::NodeVectors x0, d0;
    corner_vectors(q, x_, d_, &x0, &d0);
    bool touched = false;
    const double offset = 0.5 * element_thickness(e);
    for (std::size_t i = 0; i < tools_.size(); ++i)
      touched |= contact_->element(e, x, d, x0, d0, offset, tools_[i], &rc, ke ? &kc : nullptr, nullptr, static_cast<int>(i));
    if (touched) {
      element::Vec24 ru;
      element::Mat24 ku;
      element::director_to_dofs(d, rc, ke ? &kc : nullptr, &ru, ke ? &ku : nullptr);
      r += ru;
      if (ke) k += ku;
    }
  }
  if (!framed_.empty()) {
    // Rotation rows and columns of framed nodes into their frames at the trial directors.
    for (int I = 0; I < 4; ++I) {
      if (!framed_[static_cast<std::size_t>(q[static_cast<std::size_t>(I)])]) continue;
      const Eigen::Matrix3d f = rotation_frame(q[static_cast<std::size_t>(I)], d[static_cast<std::size_t>(I)]);
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
  rotate_to_frames(dt_, true, &f);  // moments at framed nodes, as the element forces they balance
  return f;
}

void ShellModel::set_trial(const Eigen::VectorXd& delta, double alpha) {
  // Rotations of framed nodes come in the frames of the iterate's directors (those of the
  // tangent they were solved with).
  Eigen::VectorXd step = alpha * delta;
  rotate_to_frames(di_, false, &step);
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
  // External work of the increment (trapezoidal rule): nodal loads over the increment of their
  // DOF, each tool's force on the sheet over the move of its centre.
  for (const auto& [i, a] : loads_) load_work_ += 0.5 * (lambda_ + lambda) * a * increment_(i);
  std::vector<Eigen::Vector3d> force_before;
  if (contact_)
    for (int i = 0; i < contact_->tools(); ++i) force_before.push_back(contact_->committed_summary(i).force_on_sheet);
  // The last evaluation was at the accepted iterate: its element trial states are the ones to keep.
  x_ = xi_;
  d_ = di_;
  std::vector<double> thickness_before;
  if (contact_)
    for (int e = 0; e < num_elements(); ++e) thickness_before.push_back(element_thickness(e));
  for (auto& el : elements_) el.commit();
  if (contact_) {
    contact_->commit();
    const std::vector<double> fn = contact_->element_normal_force();
    for (int e = 0; e < num_elements(); ++e) {
      const auto ue = static_cast<std::size_t>(e);
      if (fn[ue] != 0.0) offset_release_ -= fn[ue] * 0.5 * (element_thickness(e) - thickness_before[ue]);
    }
    for (std::size_t i = 0; i < tools_.size(); ++i) {
      const Eigen::Vector3d after = contact_->committed_summary(static_cast<int>(i)).force_on_sheet;
      tool_work_ += 0.5 * (force_before[i] + after).dot(tools_[i].centre - tools_[i].centre_committed);
    }
    for (auto& t : tools_) t.centre_committed = t.centre;
  }
  increment_.setZero();
  increment_trial_.setZero();
  lambda_ = lambda;
}

void ShellModel::revert() {
  xi_ = xt_ = x_;
  di_ = dt_ = d_;
  for (auto& el : elements_) el.revert();
  if (contact_) contact_->revert();
  increment_.setZero();
  increment_trial_.setZero();
}

Eigen::VectorXd ShellModel::increment_from_committed() const {
  Eigen::VectorXd v = increment_;  // x, y, z
  rotate_to_frames(di_, true, &v);
  return v;
}

void ShellModel::save_state(io::BinaryWriter& w) const {
  w.section("shell_model");
  w.i64(num_nodes());
  w.i64(num_elements());
  w.f64(lambda_);
  w.vec3s(x_);
  w.vec3s(d_);
  w.section("elements");
  for (const auto& el : elements_) el.save_state(w);
  w.section("tools");
  w.i64(static_cast<std::int64_t>(tools_.size()));
  w.boolean(contact_ != nullptr);
  for (const auto& t : tools_) {
    w.f64(t.radius);
    w.vec3(t.centre);
    w.vec3(t.centre_committed);
    w.vec3(t.spin);
  }
  if (contact_) contact_->save_state(w);
  w.f64(tool_work_);
  w.f64(load_work_);
  w.f64(offset_release_);
}

ModelEnergies ShellModel::energies() const {
  ModelEnergies out;
  out.external_work = tool_work_ + load_work_;
  for (int e = 0; e < num_elements(); ++e) {
    const auto& q = mesh_->quads[static_cast<std::size_t>(e)];
    element::NodeVectors x, d;
    corner_vectors(q, x_, d_, &x, &d);
    const element::ElementEnergy ee = elements_[static_cast<std::size_t>(e)].energy(x, d);
    out.elastic += ee.elastic;
    out.plastic += ee.plastic;
    out.transverse_shear += ee.transverse_shear;
  }
  if (contact_) {
    out.contact_stored = contact_->stored_energy();
    out.friction_dissipation = contact_->friction_dissipation();
    out.contact_offset_release = offset_release_;
  }
  return out;
}

void ShellModel::load_state(io::BinaryReader& r) {
  r.section("shell_model");
  r.expect_count("nodes", num_nodes());
  r.expect_count("elements", num_elements());
  lambda_ = r.f64();
  x_ = r.vec3s();
  d_ = r.vec3s();
  if (x_.size() != static_cast<std::size_t>(num_nodes()) || d_.size() != x_.size())
    throw io::ArchiveError("nodal positions or directors of another model size");
  r.section("elements");
  for (auto& el : elements_) el.load_state(r);
  r.section("tools");
  r.expect_count("tools (the real one and its copies)", static_cast<std::int64_t>(tools_.size()));
  if (r.boolean() != (contact_ != nullptr)) throw io::ArchiveError("contact present in the state but not in the model, or the reverse");
  for (auto& t : tools_) {
    t.radius = r.f64();
    t.centre = r.vec3();
    t.centre_committed = r.vec3();
    t.spin = r.vec3();
  }
  if (contact_) contact_->load_state(r);
  tool_work_ = r.f64();
  load_work_ = r.f64();
  offset_release_ = r.f64();
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

ShellModel::LumpedMass ShellModel::lumped_mass() const {
  LumpedMass m;
  m.translational.assign(x_.size(), 0.0);
  m.rotational.assign(x_.size(), 0.0);
  m.drilling.assign(x_.size(), 0.0);
  for (int e = 0; e < num_elements(); ++e) {
    const double area = elements_[static_cast<std::size_t>(e)].reference_area();
    const double mass = options_.density * thickness_ * area / 4.0;
    const double inertia = mass * std::max(thickness_ * thickness_ / 12.0, area / 18.0);  // eq. 6.62
    for (int i : mesh_->quads[static_cast<std::size_t>(e)]) {
      m.translational[static_cast<std::size_t>(i)] += mass;
      m.rotational[static_cast<std::size_t>(i)] += inertia;
      m.drilling[static_cast<std::size_t>(i)] += 2.0 * inertia;  // D6 = D4 + D5 (eq. 6.61)
    }
  }
  return m;
}

io::VtuFrame ShellModel::vtu_frame() const {
  io::VtuFrame f;
  f.points = x_;
  io::VtuField u{"displacement", 3, {}}, dir{"director", 3, {}}, h{"thickness", 1, nodal_thickness()};
  for (int n = 0; n < num_nodes(); ++n) {
    const Eigen::Vector3d un = displacement(n);
    u.values.insert(u.values.end(), {un.x(), un.y(), un.z()});
    const Eigen::Vector3d& dn = director(n);
    dir.values.insert(dir.values.end(), {dn.x(), dn.y(), dn.z()});
  }
  f.point_data = {u, dir, h};
  const int layers = rule_.zeta.empty() ? 0 : static_cast<int>(rule_.zeta.size());
  io::VtuField eq_max{"eqps_max", 1, {}}, s_bot{"stress_bottom", 3, {}}, s_mid{"stress_middle", 3, {}}, s_top{"stress_top", 3, {}};
  for (int e = 0; e < num_elements(); ++e) {
    const auto& el = elements_[static_cast<std::size_t>(e)];
    double pmax = 0.0;
    Eigen::Vector3d sb = Eigen::Vector3d::Zero(), sm = sb, st = sb;
    for (int p = 0; p < element::ShellQ4::kPoints; ++p) {
      const auto& sec = el.section(p);
      for (int l = 0; l < layers; ++l) pmax = std::max(pmax, sec.layer_state(l).eqps);
      sb += 0.25 * sec.layer_state(0).stress;
      sm += 0.25 * sec.layer_state(layers / 2).stress;
      st += 0.25 * sec.layer_state(layers - 1).stress;
    }
    eq_max.values.push_back(pmax);
    for (const auto* v : {&sb, &sm, &st}) {
      auto& field = v == &sb ? s_bot : v == &sm ? s_mid : s_top;
      field.values.insert(field.values.end(), {(*v)(0), (*v)(1), (*v)(2)});
    }
  }
  f.cell_data = {eq_max, s_bot, s_mid, s_top};
  if (contact_) f.cell_data.push_back({"contact_pressure", 1, contact_->element_pressure()});
  return f;
}

}  // namespace spifit::model
