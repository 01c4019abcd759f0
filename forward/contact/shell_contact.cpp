#include "forward/contact/shell_contact.hpp"

#include "forward/element/log_strain.hpp"
#include "forward/element/quad_shape.hpp"
#include "forward/io/binary_archive.hpp"

#include <ceres/jet.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

namespace spifit::contact {

std::string ContactOptions::validate() const {
  if (!(penalty > 0.0 && std::isfinite(penalty))) return "penalty must be > 0";
  if (!(friction >= 0.0 && friction <= 2.0)) return "friction must lie in [0, 2]";
  if (!(tangential_penalty >= 0.0 && std::isfinite(tangential_penalty))) return "tangential_penalty must be >= 0";
  if (points < 1 || points > 6) return "points must be 1 to 6 per direction";
  if (surface != Surface::flat && surface != Surface::phong) return "surface must be \"flat\" or \"phong\"";
  return {};
}

namespace {

constexpr double kPhongAlpha = 0.5;  // bilinear quads: reproduces a sphere to second order (test PhongSurfaceFollowsTheDirectors)

// Tool-side surface point of an element at shape values N from its 24 p-variables (node I:
// position x_I = p[6I..6I+2], director d_I = p[6I+3..6I+5]); any scalar type (Jets give the
// derivatives). Phong: x = x_lin - alpha sum_I N_I ((x_lin - s_I) . d_I) d_I with
// s_I = x_I + offset d_I, the projection of x_lin on node I's tangent plane blended in.
template <typename T>
Eigen::Matrix<T, 3, 1> surface_at(const T* p, const Eigen::Vector4d& N, const T& h, bool phong) {
  using V = Eigen::Matrix<T, 3, 1>;
  using element::lift;
  const T zero = lift<T>(0.0);
  V s[4], d[4];
  V lin(zero, zero, zero);
  for (int I = 0; I < 4; ++I) {
    d[I] = V(p[6 * I + 3], p[6 * I + 4], p[6 * I + 5]);
    s[I] = V(p[6 * I], p[6 * I + 1], p[6 * I + 2]) + d[I] * h;
    lin += s[I] * lift<T>(N(I));
  }
  if (!phong) return lin;
  V out = lin;
  for (int I = 0; I < 4; ++I) {
    const V a = lin - s[I];
    const T height = a(0) * d[I](0) + a(1) * d[I](1) + a(2) * d[I](2);  // (Eigen's dot needs Scalar(0))
    out -= d[I] * (lift<T>(kPhongAlpha * N(I)) * height);
  }
  return out;
}

template <typename T>
Eigen::Matrix<T, 3, 1> surface_of(const T* p, const Eigen::Vector4d& N, double offset, bool phong) {
  return surface_at(p, N, element::lift<T>(offset), phong);
}

std::array<double, 24> pack(const element::NodeVectors& x, const element::NodeVectors& d) {
  std::array<double, 24> p{};
  for (std::size_t I = 0; I < 4; ++I)
    for (std::size_t k = 0; k < 3; ++k) {
      p[6 * I + k] = x[I](static_cast<Eigen::Index>(k));
      p[6 * I + 3 + k] = d[I](static_cast<Eigen::Index>(k));
    }
  return p;
}

// Gauss-Legendre points on [-1, 1] (1..6).
void gauss(int n, std::vector<double>* x, std::vector<double>* w) {
  const element::ThicknessRule r = element::gauss_legendre_rule(n);
  *x = r.zeta;
  *w = r.weight;
}

// The element's bounding sphere (its tool-side surface within `offset` of the nodes) misses the
// tool: a quick rejection before any contact point is evaluated.
bool tool_misses_element(const element::NodeVectors& x, double offset, const SphereTool& tool) {
  Eigen::Vector3d centre = 0.25 * (x[0] + x[1] + x[2] + x[3]);
  double radius = 0.0;
  for (const auto& xi : x) radius = std::max(radius, (xi - centre).norm());
  return (centre - tool.centre).norm() > tool.radius + radius + 2.0 * offset;
}

// Regularised Coulomb friction at a contact point in contact (docs/design/contact.md, "Contact
// formulation (ShellContact)"): the trial traction is the committed one minus kt times the
// slip, projected on the tangent plane (P); it sticks inside the cone |t| <= mu p and is
// returned to it otherwise. Returns the traction on the sheet t and adds its derivative with
// respect to the point to dq. xp, xp0: the surface point now and at the start of the
// increment; v = xp - tool centre, rho = |v|, n = v / rho.
Eigen::Vector3d friction_traction(const Eigen::Vector3d& xp, const Eigen::Vector3d& xp0, const Eigen::Vector3d& v,
                                  const Eigen::Vector3d& n, const Eigen::Matrix3d& P, double rho, double pressure,
                                  const Eigen::Vector3d& committed_traction, const SphereTool& tool, double kp_n, double kt,
                                  double mu, Eigen::Vector3d& slip_out, bool& sliding, Eigen::Matrix3d& dq) {
  // Slip of the sheet point relative to the tool over the increment; the committed traction
  // is zero for a point that was not in contact.
  // A spinning tool's surface point moves by spin x (xp - centre) on top of the translation.
  const Eigen::Vector3d slip = (xp - xp0) - (tool.centre - tool.centre_committed) - tool.spin.cross(v);
  slip_out = slip;
  const Eigen::Vector3d w = committed_traction - kt * slip;
  const Eigen::Vector3d ttr = P * w;
  // d(P w)/dx = -kt P (I - [spin]x) - (n.w) P / rho - n (P w)^T / rho
  Eigen::Matrix3d spin_cross;
  spin_cross << 0.0, -tool.spin.z(), tool.spin.y(), tool.spin.z(), 0.0, -tool.spin.x(), -tool.spin.y(), tool.spin.x(), 0.0;
  Eigen::Matrix3d dttr = -kt * P * (Eigen::Matrix3d::Identity() - spin_cross) - (n.dot(w) / rho) * P - n * (P * w).transpose() / rho;
  const double norm = ttr.norm(), limit = mu * pressure;
  sliding = norm > limit;
  if (!sliding) {
    dq += dttr;
    return ttr;
  }
  const Eigen::Vector3d dir = ttr / norm;
  dq += mu * dir * (-kp_n * n.transpose()) + (limit / norm) * (Eigen::Matrix3d::Identity() - dir * dir.transpose()) * dttr;
  return limit * dir;
}

// Force f on a point of the curved (Phong) surface at shape values N and its derivative kx,
// in the p-variables pv: r_p += J^T f, k_p += J^T kx J + sum_k f_k d2x_k/dp2 (nested Jets: J
// and the curvature of the curved surface with respect to the nodal variables).
void add_phong_point(const std::array<double, 24>& pv, const Eigen::Vector4d& N, double offset, const Eigen::Vector3d& f,
                     const Eigen::Matrix3d& kx, element::Vec24* rp, element::Mat24* kp) {
  using Inner = ceres::Jet<double, 24>;
  using Outer = ceres::Jet<Inner, 24>;
  std::array<Outer, 24> pj;
  for (int i = 0; i < 24; ++i) {
    Inner a(pv[static_cast<std::size_t>(i)], i);
    pj[static_cast<std::size_t>(i)] = Outer(a, i);
  }
  const Eigen::Matrix<Outer, 3, 1> xj = surface_of(pj.data(), N, offset, true);
  Eigen::Matrix<double, 3, 24> J;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 24; ++i) J(k, i) = xj(k).v(i).a;
  rp->noalias() += J.transpose() * f;
  if (kp) {
    kp->noalias() += J.transpose() * kx * J;
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 24; ++i)
        for (int j = 0; j < 24; ++j) (*kp)(i, j) += f(k) * xj(k).v(i).v(j);
  }
}

// The same on flat facets: p = (x_I, d_I): dx/dx_I = N_I, dx/dd_I = offset N_I.
void add_flat_point(const Eigen::Vector4d& N, double offset, const Eigen::Vector3d& f, const Eigen::Matrix3d& kx,
                    element::Vec24* rp, element::Mat24* kp) {
  for (int I = 0; I < 4; ++I) {
    const double nI = N(I);
    rp->segment<3>(6 * I) += nI * f;
    rp->segment<3>(6 * I + 3) += (nI * offset) * f;
    if (!kp) continue;
    for (int J = 0; J < 4; ++J) {
      const double nn = nI * N(J);
      kp->block<3, 3>(6 * I, 6 * J) += nn * kx;
      kp->block<3, 3>(6 * I, 6 * J + 3) += (nn * offset) * kx;
      kp->block<3, 3>(6 * I + 3, 6 * J) += (nn * offset) * kx;
      kp->block<3, 3>(6 * I + 3, 6 * J + 3) += (nn * offset * offset) * kx;
    }
  }
}
using SensJet = material::SensitivityScalar;
using SensVec = Eigen::Matrix<SensJet, 3, 1>;

SensJet dot(const SensVec& a, const SensVec& b) { return a(0) * b(0) + a(1) * b(1) + a(2) * b(2); }

SensVec lifted(const Eigen::Vector3d& a) { return SensVec(SensJet(a(0)), SensJet(a(1)), SensJet(a(2))); }

// A parameter's value with a unit derivative in its slot (none: a constant).
SensJet parameter(double value, int slot) {
  SensJet s(value);
  if (slot >= 0) s.v(slot) = 1.0;
  return s;
}

// The force per area on the sheet q = p n + t at a point in contact, and its tangential traction
// t, in Jets: friction_traction's law along the branch the double evaluation took (sliding: on
// the cone |t| = mu p). friction: the traction is evaluated (mu > 0, or mu a parameter).
SensVec point_force(const SensVec& xp, const SensVec& xp0, const SphereTool& tool, const SensVec& committed_traction, const SensJet& kp,
                    const SensJet& kt, const SensJet& mu, bool friction, bool sliding, SensVec* t) {
  const SensVec v = xp - lifted(tool.centre);
  const SensJet rho = sqrt(dot(v, v));
  const SensVec n = v / rho;
  const SensJet pressure = -kp * (rho - tool.radius);
  const SensJet zero(0.0);
  *t = SensVec(zero, zero, zero);
  if (!friction) return n * pressure;
  const Eigen::Vector3d& s = tool.spin;
  const SensVec spin_v(s(1) * v(2) - s(2) * v(1), s(2) * v(0) - s(0) * v(2), s(0) * v(1) - s(1) * v(0));
  const SensVec slip = (xp - xp0) - lifted(tool.centre - tool.centre_committed) - spin_v;
  const SensVec w = committed_traction - slip * kt;
  const SensVec trial = w - n * dot(n, w);
  if (!sliding) {
    *t = trial;
  } else {
    const SensJet norm2 = dot(trial, trial);
    if (norm2.a > 0.0) *t = trial * (mu * pressure / sqrt(norm2));
  }
  return n * pressure + *t;
}

// A point of the curved (Phong) surface and the rows of its Jacobian with respect to the 24
// p-variables, all with their parameter derivatives (the flat facets' Jacobian, N_I and
// offset N_I, holds none but the offset's): nested Jets, the p-variables' slots outside.
struct PhongPoint {
  SensVec x;
  Eigen::Matrix<SensJet, 3, 24> J;
};

PhongPoint phong_point(const std::array<SensJet, 24>& pj, const Eigen::Vector4d& N, const SensJet& offset) {
  using Outer = ceres::Jet<SensJet, 24>;
  std::array<Outer, 24> po;
  for (int i = 0; i < 24; ++i) po[static_cast<std::size_t>(i)] = Outer(pj[static_cast<std::size_t>(i)], i);
  const Eigen::Matrix<Outer, 3, 1> xo = surface_at(po.data(), N, Outer(offset), true);
  PhongPoint out;
  for (int k = 0; k < 3; ++k) {
    out.x(k) = xo(k).a;
    for (int i = 0; i < 24; ++i) out.J(k, i) = xo(k).v(i);
  }
  return out;
}
}  // namespace

void ShellContact::enable_sensitivities(const ParameterSlots& slots) {
  slots_ = slots;
  sensitivities_ = true;
  committed_dt_.assign(committed_.size(), TractionDerivatives::Zero());
  trial_dt_ = committed_dt_;
}

bool ShellContact::element_derivatives(int e, const element::NodeVectors& x, const element::NodeVectors& d, const element::NodeVectors& x0,
                                       const element::NodeVectors& d0, double offset, const SphereTool& tool, const ConfigurationDerivatives& dc,
                                       element::SensDofs* drp, bool keep, int tool_index) {
  if (!sensitivities_) throw std::logic_error("contact: element_derivatives without enable_sensitivities");
  const std::size_t base = static_cast<std::size_t>(e * per_element_);
  const std::size_t state = base + static_cast<std::size_t>(tool_index) * areas_.size();
  if (keep)
    for (int p = 0; p < per_element_; ++p) trial_dt_[state + static_cast<std::size_t>(p)].setZero();
  if (tool_misses_element(x, offset, tool)) return false;
  const auto pv = pack(x, d), pv0 = pack(x0, d0);
  std::array<SensJet, 24> pj, pj0;
  for (int i = 0; i < 24; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    pj[ui] = SensJet(pv[ui]);
    if (dc.p) pj[ui].v = dc.p->row(i).transpose();
    pj0[ui] = material::with_derivatives(pv0[ui], dc.p0.row(i));
  }
  const SensJet o = material::with_derivatives(offset, dc.offset);
  const SensJet kp = parameter(options_.penalty, slots_.penalty);
  const SensJet kt = options_.tangential_penalty > 0.0 ? SensJet(options_.tangential_penalty) : kp;
  const SensJet mu = parameter(options_.friction, slots_.friction);
  const bool friction = options_.friction > 0.0 || slots_.friction >= 0;
  const bool phong = options_.surface == ContactOptions::Surface::phong;
  bool any = false;
  for (int p = 0; p < per_element_; ++p) {
    const std::size_t id = base + static_cast<std::size_t>(p), sid = state + static_cast<std::size_t>(p);
    if (!trial_[sid].active) continue;
    any = true;
    const Eigen::Vector4d& N = points_[static_cast<std::size_t>(p)].N;
    std::optional<PhongPoint> curved;
    if (phong) curved = phong_point(pj, N, o);
    const SensVec xp = phong ? curved->x : surface_at(pj.data(), N, o, false), xp0 = surface_at(pj0.data(), N, o, phong);
    SensVec tc;
    for (int k = 0; k < 3; ++k) tc(k) = material::with_derivatives(committed_[sid].traction(k), committed_dt_[sid].row(k));
    SensVec t;
    const SensVec f = point_force(xp, xp0, tool, tc, kp, kt, mu, friction, trial_[sid].sliding, &t) * SensJet(-areas_[id]);
    if (keep)
      for (int k = 0; k < 3; ++k) trial_dt_[sid].row(k) = t(k).v.transpose();
    if (phong) {  // r_p = J^T f, J moving with the nodes, the directors and the offset
      for (int i = 0; i < 24; ++i) drp->row(i) += (curved->J(0, i) * f(0) + curved->J(1, i) * f(1) + curved->J(2, i) * f(2)).v.transpose();
      continue;
    }
    for (int I = 0; I < 4; ++I)
      for (int k = 0; k < 3; ++k) {
        drp->row(6 * I + k) += (f(k) * N(I)).v.transpose();
        drp->row(6 * I + 3 + k) += (f(k) * (o * N(I))).v.transpose();
      }
  }
  return any;
}

Eigen::Vector3d ShellContact::surface_point(const ContactOptions& o, const Eigen::Vector4d& N, const element::NodeVectors& x,
                                            const element::NodeVectors& d, double offset) {
  const auto p = pack(x, d);
  return surface_of(p.data(), N, offset, o.surface == ContactOptions::Surface::phong);
}

double ShellContact::surface_penetration(const ContactOptions& o, const element::NodeVectors& x, const element::NodeVectors& d,
                                         double offset, const SphereTool& tool, int samples) {
  if (samples < 2) throw std::invalid_argument("contact: surface_penetration needs >= 2 samples per direction");
  if (tool_misses_element(x, offset, tool)) return 0.0;
  const auto p = pack(x, d);
  const bool phong = o.surface == ContactOptions::Surface::phong;
  double deepest = 0.0;
  for (int j = 0; j < samples; ++j)
    for (int i = 0; i < samples; ++i) {
      const double xi = -1.0 + 2.0 * i / (samples - 1), eta = -1.0 + 2.0 * j / (samples - 1);
      const Eigen::Vector4d N = element::quad_shape(xi, eta);
      deepest = std::max(deepest, tool.radius - (surface_of(p.data(), N, offset, phong) - tool.centre).norm());
    }
  return deepest;
}

std::string ShellContact::resolution_warning(double point_depth, double surface_depth, int points) {
  if (!(surface_depth > 1.5 * point_depth)) return {};
  char buf[320];
  std::snprintf(buf, sizeof buf, "the tool reached %.3g mm into the tool-side surface where its %d x %d contact points per element "
                "felt at most %.3g mm: it sank between them (stretched elements); raise [contact] points", surface_depth, points,
                points, point_depth);
  return buf;
}

std::string ShellContact::penetration_warning(double depth, double thickness, double penalty) {
  if (!(depth > kPenetrationWarningFraction * thickness)) return {};
  char buf[320];
  std::snprintf(buf, sizeof buf, "the tool penetrated the sheet by up to %.3g mm (%.0f %% of its thickness %.3g mm) with [contact] "
                "penalty = %.3g N/mm^3: shapes come out that much too shallow; raise the penalty", depth, 100.0 * depth / thickness,
                thickness, penalty);
  return buf;
}

ShellContact::ShellContact(const mesh::Mesh& mesh, const ContactOptions& options, int tools)
    : options_(options), mesh_(&mesh), tools_(tools) {
  if (tools < 1) throw std::invalid_argument("contact: the number of tools must be >= 1");
  if (!mesh.hexes.empty()) throw std::invalid_argument("contact: the shell contact needs a mesh of quadrilaterals; this one has hexahedra");
  std::vector<double> g, w;
  gauss(options.points, &g, &w);
  const int n = options.points;
  per_element_ = n * n;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      PointGeometry pg;
      pg.N = element::quad_shape(g[static_cast<std::size_t>(i)], g[static_cast<std::size_t>(j)]);
      pg.area = w[static_cast<std::size_t>(i)] * w[static_cast<std::size_t>(j)];
      points_.push_back(pg);
    }
  const int ne = mesh.num_elements();
  areas_.resize(static_cast<std::size_t>(ne * per_element_));
  for (int e = 0; e < ne; ++e) {
    const auto& q = mesh.quads[static_cast<std::size_t>(e)];
    element::NodeVectors X;
    for (std::size_t k = 0; k < 4; ++k) X[k] = mesh.nodes[static_cast<std::size_t>(q[k])];
    for (int p = 0; p < per_element_; ++p) {
      const double xi = g[static_cast<std::size_t>(p % n)], eta = g[static_cast<std::size_t>(p / n)];
      areas_[static_cast<std::size_t>(e * per_element_ + p)] = points_[static_cast<std::size_t>(p)].area * element::quad_area_jacobian(X, xi, eta);
    }
  }
  committed_.assign(areas_.size() * static_cast<std::size_t>(tools), PointState{});
  trial_ = committed_;
}

bool ShellContact::element(int e, const element::NodeVectors& x, const element::NodeVectors& d, const element::NodeVectors& x0,
                           const element::NodeVectors& d0, double offset, const SphereTool& tool, element::Vec24* rp,
                           element::Mat24* kp, ContactSummary* summary, int tool_index) {
  const std::size_t base = static_cast<std::size_t>(e * per_element_);                    // the element's points (areas_)
  const std::size_t state = base + static_cast<std::size_t>(tool_index) * areas_.size();  // their states with this tool
  if (tool_misses_element(x, offset, tool)) {
    for (int p = 0; p < per_element_; ++p) trial_[state + static_cast<std::size_t>(p)] = PointState{};
    return false;
  }
  const double kp_n = options_.penalty;
  const double kt = options_.tangential_penalty > 0.0 ? options_.tangential_penalty : options_.penalty;
  const double mu = options_.friction;
  const bool phong = options_.surface == ContactOptions::Surface::phong;
  const auto pv = pack(x, d), pv0 = pack(x0, d0);
  bool any = false;
  for (int p = 0; p < per_element_; ++p) {
    const PointGeometry& pg = points_[static_cast<std::size_t>(p)];
    const std::size_t id = base + static_cast<std::size_t>(p), sid = state + static_cast<std::size_t>(p);
    PointState& st = trial_[sid];
    st = PointState{};
    const Eigen::Vector3d xp = surface_of(pv.data(), pg.N, offset, phong);
    const Eigen::Vector3d xp0 = surface_of(pv0.data(), pg.N, offset, phong);
    const Eigen::Vector3d v = xp - tool.centre;
    const double rho = v.norm();
    const double gap = rho - tool.radius;
    if (!(gap < 0.0) || rho <= 0.0) continue;
    any = true;
    const double da = areas_[id];
    const Eigen::Vector3d n = v / rho;
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - n * n.transpose();
    const double pressure = -kp_n * gap;
    // Force per area on the sheet q = p n + t and its derivative with respect to the point.
    Eigen::Vector3d q = pressure * n;
    Eigen::Matrix3d dq = -kp_n * n * n.transpose() + (pressure / rho) * P;
    Eigen::Vector3d t = Eigen::Vector3d::Zero();
    if (mu > 0.0) {
      t = friction_traction(xp, xp0, v, n, P, rho, pressure, committed_[sid].traction, tool, kp_n, kt, mu, st.slip, st.sliding, dq);
      q += t;
    } else {
      st.sliding = true;  // frictionless: on the cone |t| <= 0
    }
    st.active = true;
    st.traction = t;
    st.pressure = pressure;
    st.penetration = -gap;
    st.force = q * da;
    if (summary) {
      summary->force_on_sheet += st.force;
      summary->max_penetration = std::max(summary->max_penetration, -gap);
      summary->max_pressure = std::max(summary->max_pressure, pressure);
      ++summary->active_points;
      if (!st.sliding) ++summary->sticking_points;
    }
    // r = f_int - f_ext: the contact force is external.
    const Eigen::Vector3d f = -q * da;
    const Eigen::Matrix3d kx = -dq * da;
    if (phong)
      add_phong_point(pv, pg.N, offset, f, kx, rp, kp);
    else
      add_flat_point(pg.N, offset, f, kx, rp, kp);
  }
  return any;
}

void ShellContact::commit() {
  if (options_.friction > 0.0) {
    const double kt = options_.tangential_penalty > 0.0 ? options_.tangential_penalty : options_.penalty;
    for (std::size_t i = 0; i < trial_.size(); ++i) {
      const PointState &o = committed_[i], &n = trial_[i];
      if (!o.active && !n.active) continue;
      const double da = areas_[i % areas_.size()];
      dissipation_ += (-0.5 * (o.traction + n.traction).dot(n.slip) - 0.5 * (n.traction.squaredNorm() - o.traction.squaredNorm()) / kt) * da;
    }
  }
  committed_ = trial_;
  if (sensitivities_) committed_dt_ = trial_dt_;
}

double ShellContact::stored_energy() const {
  const double kt = options_.tangential_penalty > 0.0 ? options_.tangential_penalty : options_.penalty;
  double e = 0.0;
  for (std::size_t i = 0; i < committed_.size(); ++i) {
    const PointState& p = committed_[i];
    if (!p.active) continue;
    e += (0.5 * p.pressure * p.penetration + 0.5 * p.traction.squaredNorm() / kt) * areas_[i % areas_.size()];
  }
  return e;
}
void ShellContact::revert() {
  trial_ = committed_;
  if (sensitivities_) trial_dt_ = committed_dt_;
}

void ShellContact::save_state(io::BinaryWriter& w) const {
  w.i64(tools_);
  w.i64(static_cast<std::int64_t>(areas_.size()));
  for (const PointState& p : committed_) {
    w.vec3(p.traction);
    w.vec3(p.force);
    w.f64(p.pressure);
    w.f64(p.penetration);
    w.boolean(p.active);
  }
  w.f64(dissipation_);
}

void ShellContact::load_state(io::BinaryReader& r) {
  r.expect_count("contact tools", tools_);
  r.expect_count("contact points per tool", static_cast<std::int64_t>(areas_.size()));
  for (PointState& p : committed_) {
    p.traction = r.vec3();
    p.force = r.vec3();
    p.pressure = r.f64();
    p.penetration = r.f64();
    p.active = r.boolean();
  }
  dissipation_ = r.f64();
  trial_ = committed_;
}

void ShellContact::save_sensitivities(io::BinaryWriter& w, int count) const {
  if (!sensitivities_) throw std::logic_error("ShellContact::save_sensitivities before enable_sensitivities");
  w.i64(static_cast<std::int64_t>(committed_dt_.size()));
  for (const TractionDerivatives& d : committed_dt_)
    for (int k = 0; k < count; ++k) w.vec3(d.col(k));
}

void ShellContact::load_sensitivities(io::BinaryReader& r, int count) {
  if (!sensitivities_) throw std::logic_error("ShellContact::load_sensitivities before enable_sensitivities");
  r.expect_count("contact points with sensitivities", static_cast<std::int64_t>(committed_dt_.size()));
  for (TractionDerivatives& d : committed_dt_) {
    d.setZero();
    for (int k = 0; k < count; ++k) d.col(k) = r.vec3();
  }
  trial_dt_ = committed_dt_;
}

ContactSummary ShellContact::committed_summary(int tool_index) const {
  if (tool_index < 0 || tool_index >= tools_) throw std::out_of_range("contact: no tool " + std::to_string(tool_index));
  ContactSummary s;
  const auto first = committed_.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(tool_index) * areas_.size());
  for (auto it = first; it != first + static_cast<std::ptrdiff_t>(areas_.size()); ++it) {
    const PointState& p = *it;
    if (!p.active) continue;
    s.force_on_sheet += p.force;
    s.max_penetration = std::max(s.max_penetration, p.penetration);
    s.max_pressure = std::max(s.max_pressure, p.pressure);
    ++s.active_points;
    if (!p.sliding) ++s.sticking_points;
  }
  return s;
}

std::vector<double> ShellContact::element_normal_force() const {
  std::vector<double> out(static_cast<std::size_t>(mesh_->num_elements()), 0.0);
  for (std::size_t i = 0; i < committed_.size(); ++i) {
    if (!committed_[i].active) continue;
    const std::size_t k = i % areas_.size();
    out[k / static_cast<std::size_t>(per_element_)] += committed_[i].pressure * areas_[k];
  }
  return out;
}

std::vector<double> ShellContact::element_pressure() const {
  std::vector<double> out(static_cast<std::size_t>(mesh_->num_elements()), 0.0);
  for (std::size_t i = 0; i < committed_.size(); ++i) {
    const std::size_t e = (i % areas_.size()) / static_cast<std::size_t>(per_element_);
    out[e] = std::max(out[e], committed_[i].pressure);
  }
  return out;
}

}  // namespace spifit::contact
