#include "forward/model/moving_sphere_contact.hpp"

#include "forward/element/director.hpp"
#include "forward/io/binary_archive.hpp"
#include "forward/element/quad_shape.hpp"
#include "forward/model/explicit_mass.hpp"
#include "forward/contact/normal_contact_lcp.hpp"
#include "forward/model/rotation_frames.hpp"
#include "forward/model/shell_model.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace spifit::model {

namespace {

constexpr double kNeighbourhood = 1.5;  // s of thesis eq. 5.13
constexpr int kMaxSweeps = 200;         // projected Gauss-Seidel sweeps of one solve (with friction)
constexpr int kMaxActiveSets = 1000;    // active sets of one frictionless solve
constexpr double kGapTolerance = 1e-12; // of the largest gap: a frictionless solve's gaps after the step
// The tool travel, in thicknesses, over which the tool-side surface's offset follows a change of
// the element's thickness (MovingSphereContact::follow_thickness).
constexpr double kThicknessTravel = 0.1;

// The point of the bilinear surface through q closest to c: (xi, eta) clamped to the element.
Eigen::Vector2d closest_point(const element::NodeVectors& q, const Eigen::Vector3d& c) {
  Eigen::Vector2d z = Eigen::Vector2d::Zero();
  for (int it = 0; it < 8; ++it) {
    const Eigen::Vector3d r = element::combine(element::quad_shape(z.x(), z.y()), q) - c;
    const Eigen::Matrix<double, 2, 4> dn = element::quad_shape_derivatives(z.x(), z.y());
    Eigen::Matrix<double, 3, 2> j;
    j.col(0) = element::combine(dn.row(0).transpose(), q);
    j.col(1) = element::combine(dn.row(1).transpose(), q);
    const Eigen::Vector2d step = (j.transpose() * j).ldlt().solve(-j.transpose() * r);
    const Eigen::Vector2d next = (z + step).cwiseMax(-1.0).cwiseMin(1.0);
    const bool done = (next - z).norm() < 1e-12;
    z = next;
    if (done) break;
  }
  return z;
}

}  // namespace

struct MovingSphereContact::Point {
  int tool = 0, element = 0;
  Eigen::Vector4d shape;            // N_a at the point
  Eigen::Vector3d position;         // predicted, without contact forces
  Eigen::Vector3d current;          // the same material point now
  double spacing = 0.0;             // the element's characteristic length
  bool interior = false;            // inside its element (not on an edge or corner)
  std::array<int, 4> nodes{};
  Eigen::Vector3d n, s, t;          // unit normal (towards the tool centre) and tangents
  double gap = 0.0;                 // predicted, without contact forces
  Eigen::Vector2d slip = Eigen::Vector2d::Zero();  // s, t components of the slip correction that sticking needs
};

MovingSphereContact::MovingSphereContact(const ShellModel& model, const solver::DofConstraints& constraints, Eigen::VectorXd reduced_mass,
                                         double radius, double friction, PathFunction path, std::vector<double> copies_deg)
    : model_(model), constraints_(constraints), mass_(std::move(reduced_mass)), radius_(radius), friction_(friction), path_(std::move(path)) {
  rotations_.push_back(Eigen::Matrix3d::Identity());
  for (double a : copies_deg) rotations_.push_back(Eigen::AngleAxisd(a * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix());
  node_elements_.resize(static_cast<std::size_t>(model.num_nodes()));
  for (int e = 0; e < model.num_elements(); ++e)
    for (int n : model.mesh().quads[static_cast<std::size_t>(e)]) node_elements_[static_cast<std::size_t>(n)].push_back(e);
  neighbourhood_.resize(rotations_.size());
  last_positions_ = model.positions();
  for (int e = 0; e < model.num_elements(); ++e) thickness_.push_back(model.element_thickness(e));
}

// The tool-side surface is offset from the mid-surface by half a thickness that follows the
// committed one over a tool travel of kThicknessTravel thicknesses, not by the committed thickness
// itself. The plane-stress thickness has neither inertia nor a through-thickness stiffness: it
// changes with every step's membrane strains, which the prediction does not foresee, and the next
// solve closes the gap that change opens within one step. With the committed thickness, the
// contact forces' own strains came back through it as gaps (±8e-6 mm a step at mass scaling 1e4,
// a third of the tool's move), an oscillation that grew over the run and took the indent's force
// down by 22 % at 1e4 and 47 % at 1e3 (docs/design/explicit.md, "MST contact"). Followed over a
// travel, a step's change reaches the offset damped by the step's travel over 0.1 h (1e-3 at
// 1e4); the thinning is followed with a lag of 0.1 h of travel.
void MovingSphereContact::follow_thickness(double lambda_next) {
  const double travel = (path_(lambda_next) - path_(model_.load_factor())).norm();
  for (int e = 0; e < model_.num_elements(); ++e) {
    double& h = thickness_[static_cast<std::size_t>(e)];
    h += std::min(1.0, travel / (kThicknessTravel * h)) * (model_.element_thickness(e) - h);
  }
}

// Elements near the tool (thesis eq. 5.13: D^2 <= s (L^2 + R^2), D the distance from the centre
// to the element's nearest node, L its longer diagonal), grown from the last neighbourhood
// through shared nodes; a full scan when none of the last one qualifies.
std::vector<int> MovingSphereContact::grow_neighbourhood(int tool, const Eigen::Vector3d& centre) {
  const auto& x = model_.positions();
  const auto near = [&](int e) {
    const auto& q = model_.mesh().quads[static_cast<std::size_t>(e)];
    double d2 = std::numeric_limits<double>::infinity();
    for (int n : q) d2 = std::min(d2, (x[static_cast<std::size_t>(n)] - centre).squaredNorm());
    const double l2 = std::max((x[static_cast<std::size_t>(q[2])] - x[static_cast<std::size_t>(q[0])]).squaredNorm(),
                               (x[static_cast<std::size_t>(q[3])] - x[static_cast<std::size_t>(q[1])]).squaredNorm());
    return d2 <= kNeighbourhood * (l2 + radius_ * radius_);
  };
  std::vector<char> seen(static_cast<std::size_t>(model_.num_elements()), 0);
  std::vector<int> out, queue;
  for (int e : neighbourhood_[static_cast<std::size_t>(tool)])
    if (near(e)) queue.push_back(e);
  if (queue.empty())
    for (int e = 0; e < model_.num_elements(); ++e)
      if (near(e)) queue.push_back(e);
  for (int e : queue) seen[static_cast<std::size_t>(e)] = 1;
  while (!queue.empty()) {
    const int e = queue.back();
    queue.pop_back();
    out.push_back(e);
    for (int n : model_.mesh().quads[static_cast<std::size_t>(e)])
      for (int f : node_elements_[static_cast<std::size_t>(n)])
        if (!seen[static_cast<std::size_t>(f)]) {
          seen[static_cast<std::size_t>(f)] = 1;
          if (near(f)) queue.push_back(f);
        }
  }
  std::sort(out.begin(), out.end());  // the same order whatever the growth
  neighbourhood_[static_cast<std::size_t>(tool)] = out;
  return out;
}

Eigen::Vector3d MovingSphereContact::next_move(int node, const Eigen::VectorXd& increment) const {
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    for (const auto& term : constraints_.expansion(ShellModel::dof(node, k))) m(k) += term.coefficient * increment(term.reduced);
  return m;
}

Eigen::Vector3d MovingSphereContact::next_director(int node, const Eigen::VectorXd& increment) const {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    for (const auto& term : constraints_.expansion(ShellModel::dof(node, 3 + k))) r(k) += term.coefficient * increment(term.reduced);
  const Eigen::Vector3d& d = model_.director(node);
  if (model_.has_rotation_frame(node)) r = model_.rotation_frame(node, d) * r;  // framed: in the node's frame
  return element::rotate_by_vector(d, r);
}

std::vector<MovingSphereContact::Point> MovingSphereContact::candidates(int tool, double lambda_next, const Eigen::VectorXd& increment) {
  const auto& x = model_.positions();
  const Eigen::Matrix3d& R = rotations_[static_cast<std::size_t>(tool)];
  const Eigen::Vector3d c_next = R * path_(lambda_next), c_now = R * path_(model_.load_factor());
  std::vector<Point> found;
  for (int e : grow_neighbourhood(tool, c_next)) {
    const auto& q = model_.mesh().quads[static_cast<std::size_t>(e)];
    const double half = 0.5 * thickness_[static_cast<std::size_t>(e)];
    element::NodeVectors pred, now;
    for (std::size_t a = 0; a < 4; ++a) {
      now[a] = x[static_cast<std::size_t>(q[a])] + half * model_.director(q[a]);
      pred[a] = x[static_cast<std::size_t>(q[a])] + next_move(q[a], increment) + half * next_director(q[a], increment);
    }
    const Eigen::Vector2d z = closest_point(pred, c_next);
    Point p;
    p.tool = tool;
    p.element = e;
    p.shape = element::quad_shape(z.x(), z.y());
    for (std::size_t a = 0; a < 4; ++a) p.nodes[a] = q[a];
    const Eigen::Vector3d at = element::combine(p.shape, pred), at_now = element::combine(p.shape, now);
    p.position = at;
    p.current = at_now;
    p.spacing = element_length(model_, e);
    p.interior = z.cwiseAbs().maxCoeff() < 1.0 - 1e-9;
    const Eigen::Vector3d to_centre = c_next - at;
    if (to_centre.norm() < 1e-12) continue;  // the surface through the tool centre: nothing sensible to do
    p.gap = to_centre.norm() - radius_;
    // The penetration the last solve left, where the tool is now.
    stats_.max_penetration = std::max(stats_.max_penetration, radius_ - (c_now - at_now).norm());
    if (p.gap > 2.0 * half) continue;  // too far to be pushed into contact by one step
    p.n = to_centre.normalized();
    p.s = least_aligned_normal(p.n);
    p.t = p.n.cross(p.s);
    const Eigen::Vector3d need = (c_next - c_now) - (at - at_now);  // the tool's move relative to the point's
    p.slip = Eigen::Vector2d(p.s.dot(need), p.t.dot(need));
    found.push_back(p);
  }
  return found;
}

std::vector<MovingSphereContact::Point> MovingSphereContact::distinct(const std::vector<Point>& found) const {
  // A point on an element's boundary is the same contact as the interior point of a neighbour
  // across that boundary (or as the same boundary point of another element): keep one. Only when
  // that other point is at least as deep: the tool-side surfaces of neighbours are offset by
  // their own thicknesses, so they step at a shared edge (1.126 against 1.030 mm where the tool
  // thins one element and not yet the next, on the short cone), and an owner sharing a corner
  // only is elsewhere. A deeper boundary point dropped there was left out of the solve and the
  // tool went into the sheet (0.18 mm on the short cone at mass scaling 1e6).
  const auto touches = [](const Point& boundary, const Point& other) {
    for (int a = 0; a < 4; ++a)
      if (boundary.shape(a) > 1e-9 && std::find(other.nodes.begin(), other.nodes.end(), boundary.nodes[static_cast<std::size_t>(a)]) != other.nodes.end())
        return true;
    return false;
  };
  std::vector<Point> kept;
  for (std::size_t i = 0; i < found.size(); ++i) {
    bool owned = false;
    for (std::size_t j = 0; j < found.size() && !owned && !found[i].interior; ++j)
      if (j != i && touches(found[i], found[j]))
        owned = (found[j].interior || (j < i && (found[j].current - found[i].current).norm() < 1e-6 * radius_)) && found[j].gap <= found[i].gap;
    if (!owned) kept.push_back(found[i]);
  }
  // Points closer than a quarter of an element to a deeper one are the same contact (the
  // closest points of the elements around a node the tool sits on all lie near that node):
  // kept apart, they make the system nearly singular.
  std::sort(kept.begin(), kept.end(), [](const Point& a, const Point& b) { return a.gap < b.gap || (a.gap == b.gap && a.element < b.element); });
  std::vector<Point> out;
  for (const Point& p : kept) {
    const bool near = std::any_of(out.begin(), out.end(), [&](const Point& q) {
      return (q.position - p.position).norm() < 0.25 * std::min(p.spacing, q.spacing);
    });
    if (!near) out.push_back(p);
  }
  return out;
}

// W: the change of (n.dp, s.dp, t.dp) of every point over the next step per unit force on the
// sheet along each point's own (n, s, t), dt^2 E T M^-1 T^T E^T (symmetric, positive
// semi-definite); E spreads a point's axes to its element's nodes by the shape functions.
Eigen::MatrixXd MovingSphereContact::compliance(const std::vector<Point>& points, double dt) const {
  const int k = static_cast<int>(points.size());
  std::map<int, int> slot;  // the nodes involved
  for (const Point& p : points)
    for (int n : p.nodes) slot.emplace(n, 0);
  int u = 0;
  for (auto& [n, s] : slot) s = u++;
  std::map<int, std::vector<std::pair<int, double>>> by_reduced;  // reduced -> (involved DOF, coefficient)
  for (const auto& [n, s] : slot)
    for (int c = 0; c < 3; ++c)
      for (const auto& term : constraints_.expansion(ShellModel::dof(n, c))) by_reduced[term.reduced].push_back({3 * s + c, term.coefficient});
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(3 * u, 3 * u);  // T M^-1 T^T among the involved translations
  for (const auto& [j, list] : by_reduced)
    for (const auto& [p, cp] : list)
      for (const auto& [q, cq] : list) G(p, q) += cp * cq / mass_(j);
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(3 * k, 3 * u);
  for (int i = 0; i < k; ++i) {
    const Point& p = points[static_cast<std::size_t>(i)];
    for (int a = 0; a < 4; ++a) {
      const int s = 3 * slot.at(p.nodes[static_cast<std::size_t>(a)]);
      E.block<1, 3>(3 * i, s) += p.shape(a) * p.n.transpose();
      E.block<1, 3>(3 * i + 1, s) += p.shape(a) * p.s.transpose();
      E.block<1, 3>(3 * i + 2, s) += p.shape(a) * p.t.transpose();
    }
  }
  return (dt * dt) * E * G * E.transpose();
}

// The conditions of thesis Fig. 5.7 as a complementarity problem, solved by projected
// Gauss-Seidel: per point, the normal force P >= 0 that closes the gap (or none where the gap
// stays open), then the friction that cancels the slip, cut to the cone |F| <= mu P (sliding).
// Unlike switching the points' states all at once, the sweeps converge to the one solution when
// W is positive definite, so the contact does not hop between neighbouring points. Returns the
// force on the sheet along each point's (n, s, t): (-P, F_s, F_t).
Eigen::VectorXd MovingSphereContact::solve(const std::vector<Point>& points, const Eigen::MatrixXd& W) {
  if (friction_ == 0.0) return solve_frictionless(points, W);
  const int k = static_cast<int>(points.size());
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(3 * k), w_phi = Eigen::VectorXd::Zero(3 * k);
  const auto apply = [&](int i, const Eigen::Vector3d& delta) {
    if (delta.squaredNorm() == 0.0) return;
    w_phi.noalias() += W.middleCols<3>(3 * i) * delta;
    phi.segment<3>(3 * i) += delta;
  };
  bool converged = false;
  int it = 0;
  double scale = 0.0;  // of the forces, for the convergence test
  for (; it < kMaxSweeps && !converged; ++it) {
    double change = 0.0;
    for (int i = 0; i < k; ++i) {
      const Point& p = points[static_cast<std::size_t>(i)];
      const Eigen::Matrix3d Wii = W.block<3, 3>(3 * i, 3 * i);
      if (!(Wii(0, 0) > 0.0)) continue;  // a point on clamped nodes only: nothing moves it
      // Normal: the gap after the step is gap - (W phi)_n; P from closing it, never negative.
      const double P_old = -phi(3 * i);
      const double P = std::max(0.0, P_old + (w_phi(3 * i) - p.gap) / Wii(0, 0));
      apply(i, Eigen::Vector3d(P_old - P, 0.0, 0.0));
      // Tangential: the slip against the tool is (W phi)_{s,t} - the slip needed; sticking cancels it.
      const Eigen::Vector2d F_old = phi.segment<2>(3 * i + 1);
      Eigen::Vector2d F = Eigen::Vector2d::Zero();
      if (friction_ > 0.0 && P > 0.0) {
        F = F_old - Wii.block<2, 2>(1, 1).ldlt().solve(w_phi.segment<2>(3 * i + 1) - p.slip);
        if (F.norm() > friction_ * P) F *= friction_ * P / F.norm();
      }
      apply(i, Eigen::Vector3d(0.0, F.x() - F_old.x(), F.y() - F_old.y()));
      change = std::max({change, std::abs(P - P_old), (F - F_old).norm()});
      scale = std::max({scale, P, F.norm()});
    }
    converged = change <= 1e-10 * scale || scale == 0.0;
  }
  ++stats_.solves;
  stats_.sweeps += it;
  if (!converged) ++stats_.unconverged;
  return phi;
}

// Without friction the problem is the normal one alone, solved exactly (normal_contact_lcp.hpp).
Eigen::VectorXd MovingSphereContact::solve_frictionless(const std::vector<Point>& points, const Eigen::MatrixXd& W) {
  const int k = static_cast<int>(points.size());
  Eigen::MatrixXd M(k, k);
  Eigen::VectorXd q(k);
  double scale = 0.0;
  for (int i = 0; i < k; ++i) {
    q(i) = points[static_cast<std::size_t>(i)].gap;
    scale = std::max(scale, std::abs(q(i)));
    for (int j = 0; j < k; ++j) M(i, j) = W(3 * i, 3 * j);
  }
  const contact::NormalContactSolution s = contact::solve_normal_contact(M, q, kGapTolerance * scale, kMaxActiveSets);
  ++stats_.solves;
  stats_.sweeps += s.active_sets;
  if (!s.converged) ++stats_.unconverged;
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(3 * k);
  for (int i = 0; i < k; ++i) phi(3 * i) = -s.force(i);
  return phi;
}

Eigen::VectorXd MovingSphereContact::forces(double dt, double lambda_next, const Eigen::VectorXd& next_increment) {
  follow_thickness(lambda_next);
  std::vector<Point> points;
  for (int tool = 0; tool < static_cast<int>(rotations_.size()); ++tool)
    for (const Point& p : distinct(candidates(tool, lambda_next, next_increment))) points.push_back(p);
  const int k = static_cast<int>(points.size());
  last_points_ = k;
  Eigen::VectorXd f_full = Eigen::VectorXd::Zero(model_.num_dofs());
  std::map<int, Eigen::Vector3d> by_node;
  tool_force_.setZero();
  if (k > 0) {
    stats_.max_points = std::max(stats_.max_points, k);
    const Eigen::VectorXd phi = solve(points, compliance(points, dt));
    for (int i = 0; i < k; ++i) {
      const Point& p = points[static_cast<std::size_t>(i)];
      const Eigen::Vector3d on_sheet = phi(3 * i) * p.n + phi(3 * i + 1) * p.s + phi(3 * i + 2) * p.t;
      for (int a = 0; a < 4; ++a) {  // eq. 5.25
        auto [it, fresh] = by_node.emplace(p.nodes[static_cast<std::size_t>(a)], Eigen::Vector3d::Zero());
        it->second += p.shape(a) * on_sheet;
      }
      tool_force_ -= rotations_[static_cast<std::size_t>(p.tool)].transpose() * on_sheet;
      const double P = -phi(3 * i);
      if (friction_ > 0.0 && P > 0.0)
        stats_.max_friction_ratio = std::max(stats_.max_friction_ratio, phi.segment<2>(3 * i + 1).norm() / (friction_ * P));
    }
  }
  std::vector<std::pair<int, Eigen::Vector3d>> new_forces;
  for (const auto& [n, f] : by_node) {
    if (f.squaredNorm() == 0.0) continue;
    new_forces.push_back({n, f});
    f_full.segment<3>(ShellModel::dof(n, 0)) += f;
  }
  // Work on the sheet: each step's force times half the moves of the steps on either side of
  // it (the central-difference pairing of a force with its displacement).
  const auto& x = model_.positions();
  for (const auto* list : {&last_forces_, &new_forces})
    for (const auto& [n, f] : *list) stats_.work += 0.5 * f.dot(x[static_cast<std::size_t>(n)] - last_positions_[static_cast<std::size_t>(n)]);
  last_forces_ = std::move(new_forces);
  last_positions_ = x;
  return f_full;
}

namespace {

void save_indices(io::BinaryWriter& w, const std::vector<int>& v) {
  w.i64(static_cast<std::int64_t>(v.size()));
  for (int i : v) w.i64(i);
}

// An index read from a checkpoint, refused outside [0, size).
int load_index(io::BinaryReader& r, int size, const char* what) {
  const std::int64_t i = r.i64();
  if (i < 0 || i >= size) throw io::ArchiveError(std::string("MST state: invalid ") + what + " " + std::to_string(i));
  return static_cast<int>(i);
}

std::vector<int> load_indices(io::BinaryReader& r, int size, const char* what) {
  const std::int64_t n = r.i64();
  if (n < 0 || n > size) throw io::ArchiveError(std::string("MST state: invalid ") + what + " count " + std::to_string(n));
  std::vector<int> v;
  for (std::int64_t k = 0; k < n; ++k) v.push_back(load_index(r, size, what));
  return v;
}

}  // namespace

void MovingSphereContact::save_state(io::BinaryWriter& w) const {
  w.section("mst");
  w.f64s(thickness_);
  w.i64(static_cast<std::int64_t>(neighbourhood_.size()));
  for (const auto& elements : neighbourhood_) save_indices(w, elements);
  w.i64(static_cast<std::int64_t>(last_forces_.size()));
  for (const auto& [node, f] : last_forces_) {
    w.i64(node);
    w.vec3(f);
  }
  w.vec3s(last_positions_);
  w.vec3(tool_force_);
  for (long n : {stats_.solves, stats_.sweeps, stats_.unconverged, static_cast<long>(stats_.max_points), static_cast<long>(last_points_)}) w.i64(n);
  for (double x : {stats_.max_penetration, stats_.max_friction_ratio, stats_.work}) w.f64(x);
}

void MovingSphereContact::load_state(io::BinaryReader& r) {
  r.section("mst");
  const int ne = model_.num_elements(), nn = model_.num_nodes();
  std::vector<double> thickness = r.f64s();
  if (thickness.size() != static_cast<std::size_t>(ne)) throw io::ArchiveError("MST state of another model size");
  r.expect_count("MST tools", static_cast<std::int64_t>(rotations_.size()));
  for (auto& elements : neighbourhood_) elements = load_indices(r, ne, "neighbourhood element");
  const std::int64_t nf = r.i64();
  if (nf < 0 || nf > nn) throw io::ArchiveError("MST state: invalid force count " + std::to_string(nf));
  last_forces_.clear();
  for (std::int64_t k = 0; k < nf; ++k) {
    const int node = load_index(r, nn, "node");
    last_forces_.emplace_back(node, r.vec3());
  }
  last_positions_ = r.vec3s();
  if (last_positions_.size() != static_cast<std::size_t>(nn)) throw io::ArchiveError("MST state of another model size");
  tool_force_ = r.vec3();
  stats_.solves = r.i64();
  stats_.sweeps = r.i64();
  stats_.unconverged = r.i64();
  stats_.max_points = static_cast<int>(r.i64());
  last_points_ = static_cast<int>(r.i64());
  stats_.max_penetration = r.f64();
  stats_.max_friction_ratio = r.f64();
  stats_.work = r.f64();
  thickness_ = std::move(thickness);
}

}  // namespace spifit::model
