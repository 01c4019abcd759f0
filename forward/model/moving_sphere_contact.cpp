#include "forward/model/moving_sphere_contact.hpp"

#include "forward/element/quad_shape.hpp"
#include "forward/model/shell_model.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace spifit::model {

namespace {

constexpr double kNeighbourhood = 1.5;  // s of thesis eq. 5.13
constexpr int kMaxIterations = 30;      // state iterations of one solve

enum class State { none, stick, slide };

// Two unit vectors normal to n and to each other.
void tangent_axes(const Eigen::Vector3d& n, Eigen::Vector3d* s, Eigen::Vector3d* t) {
  const Eigen::Vector3d a = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  *s = n.cross(a).normalized();
  *t = n.cross(*s);
}

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
  std::array<int, 4> nodes{};
  Eigen::Vector3d n, s, t;          // unit normal (towards the tool centre) and tangents
  double gap = 0.0;                 // predicted, without contact forces
  Eigen::Vector2d slip = Eigen::Vector2d::Zero();  // s, t components of the slip correction that sticking needs
  State state = State::none;
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // of the friction force while sliding
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

Eigen::VectorXd MovingSphereContact::forces(double dt, double lambda_next, const Eigen::VectorXd& next_increment) {
  const auto& x = model_.positions();
  const auto& d = model_.directors();
  // Where a node's translation goes over the next step without contact forces.
  const auto move = [&](int node) {
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      for (const auto& term : constraints_.expansion(ShellModel::dof(node, k))) m(k) += term.coefficient * next_increment(term.reduced);
    return m;
  };
  const double lambda_now = model_.load_factor();
  std::vector<Point> points;
  for (int tool = 0; tool < static_cast<int>(rotations_.size()); ++tool) {
    const Eigen::Matrix3d& R = rotations_[static_cast<std::size_t>(tool)];
    const Eigen::Vector3d c_next = R * path_(lambda_next), c_now = R * path_(lambda_now);
    struct Candidate {
      Point p;
      bool interior;
    };
    std::vector<Candidate> found;
    for (int e : grow_neighbourhood(tool, c_next)) {
      const auto& q = model_.mesh().quads[static_cast<std::size_t>(e)];
      const double half = 0.5 * model_.element_thickness(e);
      element::NodeVectors pred, now;
      for (int a = 0; a < 4; ++a) {
        const auto n = static_cast<std::size_t>(q[static_cast<std::size_t>(a)]);
        now[static_cast<std::size_t>(a)] = x[n] + half * d[n];
        pred[static_cast<std::size_t>(a)] = now[static_cast<std::size_t>(a)] + move(q[static_cast<std::size_t>(a)]);
      }
      const Eigen::Vector2d z = closest_point(pred, c_next);
      Point p;
      p.tool = tool;
      p.element = e;
      p.shape = element::quad_shape(z.x(), z.y());
      for (int a = 0; a < 4; ++a) p.nodes[static_cast<std::size_t>(a)] = q[static_cast<std::size_t>(a)];
      const Eigen::Vector3d at = element::combine(p.shape, pred), at_now = element::combine(p.shape, now);
      const Eigen::Vector3d to_centre = c_next - at;
      if (to_centre.norm() < 1e-12) continue;  // the surface through the tool centre: nothing sensible to do
      p.gap = to_centre.norm() - radius_;
      // The penetration the last solve left, where the tool is now.
      stats_.max_penetration = std::max(stats_.max_penetration, radius_ - (c_now - at_now).norm());
      if (p.gap > 2.0 * half) continue;  // too far to be pushed into contact by one step
      p.n = to_centre.normalized();
      tangent_axes(p.n, &p.s, &p.t);
      const Eigen::Vector3d need = (c_next - c_now) - (at - at_now);  // the tool's move relative to the point's
      p.slip = Eigen::Vector2d(p.s.dot(need), p.t.dot(need));
      const bool interior = z.cwiseAbs().maxCoeff() < 1.0 - 1e-9;
      found.push_back({p, interior});
    }
    // A point on an element's boundary is the same contact as the interior point of a neighbour
    // across that boundary (or as the same boundary point of another element): keep one.
    for (std::size_t i = 0; i < found.size(); ++i) {
      if (!found[i].interior) {
        bool owned = false;
        const Eigen::Vector3d pi = element::combine(found[i].p.shape, [&] {
          element::NodeVectors v;
          for (int a = 0; a < 4; ++a) v[static_cast<std::size_t>(a)] = x[static_cast<std::size_t>(found[i].p.nodes[static_cast<std::size_t>(a)])];
          return v;
        }());
        for (std::size_t j = 0; j < found.size() && !owned; ++j) {
          if (j == i) continue;
          const bool shares = std::any_of(found[j].p.nodes.begin(), found[j].p.nodes.end(), [&](int n) {
            for (int a = 0; a < 4; ++a)
              if (found[i].p.shape(a) > 1e-9 && found[i].p.nodes[static_cast<std::size_t>(a)] == n) return true;
            return false;
          });
          if (!shares) continue;
          if (found[j].interior) owned = true;
          else if (j < i) {
            element::NodeVectors v;
            for (int a = 0; a < 4; ++a) v[static_cast<std::size_t>(a)] = x[static_cast<std::size_t>(found[j].p.nodes[static_cast<std::size_t>(a)])];
            owned = (element::combine(found[j].p.shape, v) - pi).norm() < 1e-6 * radius_;
          }
        }
        if (owned) continue;
      }
      points.push_back(found[i].p);
    }
  }
  const int k = static_cast<int>(points.size());
  last_points_ = k;
  Eigen::VectorXd f_full = Eigen::VectorXd::Zero(model_.num_dofs());
  std::vector<std::pair<int, Eigen::Vector3d>> new_forces;
  tool_force_.setZero();
  if (k > 0) {
    stats_.max_points = std::max(stats_.max_points, k);
    // The nodes involved, and the translational block of T M^-1 T^T among them.
    std::map<int, int> slot;
    for (const Point& p : points)
      for (int n : p.nodes) slot.emplace(n, 0);
    int u = 0;
    for (auto& [n, s] : slot) s = u++;
    std::map<int, std::vector<std::pair<int, double>>> by_reduced;  // reduced -> (involved DOF, coefficient)
    for (const auto& [n, s] : slot)
      for (int c = 0; c < 3; ++c)
        for (const auto& term : constraints_.expansion(ShellModel::dof(n, c))) by_reduced[term.reduced].push_back({3 * s + c, term.coefficient});
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(3 * u, 3 * u);
    for (const auto& [j, list] : by_reduced)
      for (const auto& [p, cp] : list)
        for (const auto& [q, cq] : list) G(p, q) += cp * cq / mass_(j);
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(3 * k, 3 * u), D = Eigen::MatrixXd::Zero(3 * k, 3 * u);
    for (int i = 0; i < k; ++i) {
      const Point& p = points[static_cast<std::size_t>(i)];
      for (int a = 0; a < 4; ++a) {
        const int s = 3 * slot.at(p.nodes[static_cast<std::size_t>(a)]);
        const double w = p.shape(a);
        E.block<1, 3>(3 * i, s) += w * p.n.transpose();
        E.block<1, 3>(3 * i + 1, s) += w * p.s.transpose();
        E.block<1, 3>(3 * i + 2, s) += w * p.t.transpose();
        D.block<1, 3>(3 * i, s) -= w * p.n.transpose();
        D.block<1, 3>(3 * i + 1, s) += w * p.s.transpose();
        D.block<1, 3>(3 * i + 2, s) += w * p.t.transpose();
      }
    }
    const Eigen::MatrixXd H = (dt * dt) * E * G * D.transpose();  // change of (n.dp, s.dp, t.dp) per unit (P, Fs, Ft)
    for (Point& p : points) p.state = p.gap < 0.0 ? (friction_ > 0.0 ? State::stick : State::slide) : State::none;
    Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * k);
    bool converged = false;
    int it = 0;
    for (; it < kMaxIterations && !converged; ++it) {
      // Points without contact carry no force: the system is that of the others.
      std::vector<int> active;
      for (int i = 0; i < k; ++i)
        if (points[static_cast<std::size_t>(i)].state != State::none) active.push_back(i);
      const int na = static_cast<int>(active.size());
      Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 * na, 3 * na);
      Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * na);
      for (int r = 0; r < na; ++r) {
        const int i = active[static_cast<std::size_t>(r)];
        const Point& p = points[static_cast<std::size_t>(i)];
        const auto take_row = [&](int row_a, int row_h) {
          for (int c = 0; c < na; ++c) A.block<1, 3>(row_a, 3 * c) = H.block<1, 3>(row_h, 3 * active[static_cast<std::size_t>(c)]);
        };
        take_row(3 * r, 3 * i);
        b(3 * r) = p.gap;
        if (p.state == State::stick) {
          take_row(3 * r + 1, 3 * i + 1);
          take_row(3 * r + 2, 3 * i + 2);
          b(3 * r + 1) = p.slip.x();
          b(3 * r + 2) = p.slip.y();
        } else {  // F_f = mu P along the last direction (eq. 5.30)
          A(3 * r + 1, 3 * r + 1) = A(3 * r + 2, 3 * r + 2) = 1.0;
          A(3 * r + 1, 3 * r) = -friction_ * p.direction.x();
          A(3 * r + 2, 3 * r) = -friction_ * p.direction.y();
        }
      }
      y.setZero();
      if (na > 0) {
        const Eigen::VectorXd ya = A.colPivHouseholderQr().solve(b);
        for (int r = 0; r < na; ++r) y.segment<3>(3 * active[static_cast<std::size_t>(r)]) = ya.segment<3>(3 * r);
      }
      const Eigen::VectorXd change = H * y;
      converged = true;
      for (int i = 0; i < k; ++i) {
        Point& p = points[static_cast<std::size_t>(i)];
        const double P = y(3 * i);
        const Eigen::Vector2d F(y(3 * i + 1), y(3 * i + 2));
        State next = p.state;
        if (p.state == State::none) {
          if (p.gap - change(3 * i) < -1e-9 * radius_) next = friction_ > 0.0 ? State::stick : State::slide;
        } else if (P < 0.0) {
          next = State::none;
        } else if (p.state == State::stick && F.norm() > friction_ * P * (1.0 + 1e-9)) {
          next = State::slide;
          p.direction = F.normalized();
        } else if (p.state == State::slide && friction_ > 0.0 && it < kMaxIterations / 3) {  // later: no way back, no cycling
          const Eigen::Vector2d slip(change(3 * i + 1) - p.slip.x(), change(3 * i + 2) - p.slip.y());  // the point's slip against the tool
          if (slip.dot(F) > 0.0) next = State::stick;
        }
        if (next != p.state) {
          if (next == State::slide && p.direction.squaredNorm() == 0.0) p.direction = F.squaredNorm() > 0.0 ? F.normalized() : Eigen::Vector2d(1.0, 0.0);
          p.state = next;
          converged = false;
        }
      }
    }
    ++stats_.solves;
    stats_.iterations += it;
    if (!converged) ++stats_.unconverged;
    {
      // The law holds at every point whatever the states did: no pull and the friction inside
      // its cone. Where the states still change, or where close points make the system nearly
      // singular (its least-squares solution then misses some rows), this costs a small
      // penetration or slip, which the next step's solve takes up.
      for (int i = 0; i < k; ++i) {
        const double P = y(3 * i);
        if (points[static_cast<std::size_t>(i)].state == State::none || P <= 0.0) {
          y.segment<3>(3 * i).setZero();
          continue;
        }
        const double F = std::hypot(y(3 * i + 1), y(3 * i + 2));
        if (F > friction_ * P) y.segment<2>(3 * i + 1) *= friction_ * P / F;
      }
    }
    const Eigen::VectorXd f_u = D.transpose() * y;
    for (const auto& [n, s] : slot) {
      const Eigen::Vector3d f = f_u.segment<3>(3 * s);
      if (f.squaredNorm() == 0.0) continue;
      new_forces.push_back({n, f});
      f_full.segment<3>(ShellModel::dof(n, 0)) += f;
    }
    for (int i = 0; i < k; ++i) {
      const Point& p = points[static_cast<std::size_t>(i)];
      const double P = y(3 * i);
      const Eigen::Vector3d on_sheet = -P * p.n + y(3 * i + 1) * p.s + y(3 * i + 2) * p.t;
      tool_force_ -= rotations_[static_cast<std::size_t>(p.tool)].transpose() * on_sheet;
      if (friction_ > 0.0 && P > 0.0)
        stats_.max_friction_ratio = std::max(stats_.max_friction_ratio, std::hypot(y(3 * i + 1), y(3 * i + 2)) / (friction_ * P));
    }
  }
  // Work on the sheet: each step's force times half the moves of the steps on either side of
  // it (the central-difference pairing of a force with its displacement).
  for (const auto* list : {&last_forces_, &new_forces})
    for (const auto& [n, f] : *list) stats_.work += 0.5 * f.dot(x[static_cast<std::size_t>(n)] - last_positions_[static_cast<std::size_t>(n)]);
  last_forces_ = std::move(new_forces);
  last_positions_ = x;
  return f_full;
}

}  // namespace spifit::model
