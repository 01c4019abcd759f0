#include "forward/mesh/disc_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace spifit::mesh {

namespace {

// Radial positions s in [0, 1] of the ring's node layers: geometric grading, or (when a band is
// given) a density band with more elements per mm in it, by inverting the cumulative density.
std::vector<double> ring_layers(int n, double r0, double r1, const DiscOptions& o) {
  const auto g = graded_points(0.0, 1.0, n, o.radial_grading);
  if (!(o.band_outer > o.band_inner) || o.band_factor == 1.0) return g;
  // Density rho(s) = 1 + (f - 1) [r(s) in band]; place nodes at equal increments of its integral.
  const int fine = 4000;
  std::vector<double> s(fine + 1), cum(fine + 1, 0.0);
  for (int i = 0; i <= fine; ++i) s[i] = static_cast<double>(i) / fine;
  for (int i = 1; i <= fine; ++i) {
    const double mid = 0.5 * (s[i - 1] + s[i]);
    const double r = r0 + (r1 - r0) * mid;
    const double rho = (r >= o.band_inner && r <= o.band_outer) ? o.band_factor : 1.0;
    cum[i] = cum[i - 1] + rho * (s[i] - s[i - 1]);
  }
  std::vector<double> out(n + 1);
  for (int k = 0; k <= n; ++k) {
    const double target = cum[fine] * k / n;
    const auto it = std::lower_bound(cum.begin(), cum.end(), target);
    const int i = std::clamp(static_cast<int>(it - cum.begin()), 1, fine);
    const double t = (target - cum[i - 1]) / std::max(cum[i] - cum[i - 1], 1e-300);
    out[k] = s[i - 1] + t * (s[i] - s[i - 1]);
  }
  out[0] = 0.0;
  out[n] = 1.0;
  return out;
}

}  // namespace

Mesh disc_mesh(const DiscOptions& o) {
  if (!(o.radius > 0)) throw std::invalid_argument("radius must be > 0");
  if (!(o.angle_deg > 0 && o.angle_deg <= 360)) throw std::invalid_argument("angle must lie in (0, 360]");
  if (o.elements_per_45deg < 2) throw std::invalid_argument("elements_per_45deg must be >= 2");
  if (!(o.radial_grading > 0 && o.band_factor > 0)) throw std::invalid_argument("grading and band factor must be > 0");
  const double pi = std::numbers::pi;
  const int sectors = static_cast<int>(std::ceil(o.angle_deg / 90.0 - 1e-9));
  const double beta = o.angle_deg / sectors * pi / 180.0;  // sub-sector angle
  // Even number of rim elements per sub-sector: n per kite side.
  const int n = std::max(1, static_cast<int>(std::lround(o.elements_per_45deg * (beta * 180.0 / pi) / 45.0 / 2.0)));
  const double rim_h = o.radius * beta / (2 * n);
  // Core radius: the kite's sides have n elements of about the rim element size (default).
  const double rc = o.core_radius > 0 ? o.core_radius : std::min(0.6 * o.radius, n * rim_h * 1.2);
  if (!(rc < o.radius)) throw std::invalid_argument("core radius must be smaller than the radius");
  const int m = o.radial_elements > 0 ? o.radial_elements : std::max(1, static_cast<int>(std::lround((o.radius - rc) / rim_h)));
  const auto layers = ring_layers(m, rc, o.radius, o);

  Mesh mesh;
  auto add = [&](const Eigen::Vector2d& p) {
    mesh.nodes.emplace_back(p.x(), p.y(), 0.0);
    return static_cast<int>(mesh.nodes.size()) - 1;
  };
  for (int s = 0; s < sectors; ++s) {
    const double t0 = s * beta;
    const Eigen::Vector2d O(0, 0), A = rc * Eigen::Vector2d(std::cos(t0), std::sin(t0)),
                          B = rc * Eigen::Vector2d(std::cos(t0 + beta), std::sin(t0 + beta));
    // Bisector point of a right-angled kite (A-M perpendicular to O-A): corner angles beta at
    // the axis, 90 deg at A and B, 180 deg - beta at M; a square for beta = 90 deg.
    const Eigen::Vector2d M = rc / std::cos(0.5 * beta) * Eigen::Vector2d(std::cos(t0 + 0.5 * beta), std::sin(t0 + 0.5 * beta));
    // Core: transfinite (Coons) patch on O -> A -> M -> B, parameters (u along OA, v along OB).
    auto edge = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, double t) -> Eigen::Vector2d { return p + t * (q - p); };
    std::vector<int> core((n + 1) * (n + 1));
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
        const Eigen::Vector2d bottom = edge(O, A, u), top = edge(B, M, u), left = edge(O, B, v), right = edge(A, M, v);
        const Eigen::Vector2d p = (1 - v) * bottom + v * top + (1 - u) * left + u * right -
                                  ((1 - u) * (1 - v) * O + u * (1 - v) * A + u * v * M + (1 - u) * v * B);
        core[j * (n + 1) + i] = add(p);
      }
    }
    auto cid = [&](int i, int j) { return core[j * (n + 1) + i]; };
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) mesh.quads.push_back({cid(i, j), cid(i + 1, j), cid(i + 1, j + 1), cid(i, j + 1)});
    }
    // Ring: inner polyline A -> M -> B (2n segments), outer arc; layers s in [0, 1].
    std::vector<Eigen::Vector2d> inner(2 * n + 1), outer(2 * n + 1);
    for (int k = 0; k <= 2 * n; ++k) {
      inner[k] = k <= n ? edge(A, M, static_cast<double>(k) / n) : edge(M, B, static_cast<double>(k - n) / n);
      const double th = t0 + beta * k / (2 * n);
      outer[k] = o.radius * Eigen::Vector2d(std::cos(th), std::sin(th));
    }
    std::vector<int> ring((m + 1) * (2 * n + 1));
    for (int j = 0; j <= m; ++j) {
      for (int k = 0; k <= 2 * n; ++k) ring[j * (2 * n + 1) + k] = add(inner[k] + layers[j] * (outer[k] - inner[k]));
    }
    auto rid = [&](int k, int j) { return ring[j * (2 * n + 1) + k]; };
    for (int j = 0; j < m; ++j) {
      for (int k = 0; k < 2 * n; ++k) mesh.quads.push_back({rid(k, j), rid(k, j + 1), rid(k + 1, j + 1), rid(k + 1, j)});
    }
  }
  merge_coincident_nodes(mesh, 1e-9 * o.radius);
  std::vector<int> all(mesh.quads.size());
  for (std::size_t e = 0; e < all.size(); ++e) all[e] = static_cast<int>(e);
  mesh.element_sets["all"] = all;
  const double tol = 1e-9 * o.radius;
  mesh.node_sets["axis"] = select_nodes(mesh, [&](const Eigen::Vector3d& p) { return p.head<2>().norm() <= tol; });
  mesh.node_sets["rim"] = select_nodes(mesh, [&](const Eigen::Vector3d& p) { return std::abs(p.head<2>().norm() - o.radius) <= 1e-9 * o.radius * 10; });
  if (o.angle_deg < 360.0) {
    const double g = o.angle_deg * pi / 180.0;
    const Eigen::Vector2d e1(std::cos(g), std::sin(g));
    mesh.node_sets["edge_theta0"] = select_nodes(mesh, [&](const Eigen::Vector3d& p) { return std::abs(p.y()) <= tol && p.x() >= -tol; });
    mesh.node_sets["edge_theta1"] = select_nodes(mesh, [&](const Eigen::Vector3d& p) {
      return std::abs(e1.x() * p.y() - e1.y() * p.x()) <= tol && e1.dot(p.head<2>()) >= -tol;
    });
  }
  return mesh;
}

}  // namespace spifit::mesh
