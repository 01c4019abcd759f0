#include "forward/mesh/disc_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace spifit::mesh {

namespace {

// Radial positions s in [0, 1] of the ring's node layers: geometric grading, or (when a band is
// given) a density band with band_factor times more elements per mm in it. The density is
// piecewise constant in r = r0 + (r1 - r0) s, so its integral is piecewise linear and is inverted
// exactly: layer k sits where the integral reaches k / n of its total.
std::vector<double> ring_layers(int n, double r0, double r1, const DiscOptions& o) {
  const auto g = graded_points(0.0, 1.0, n, o.radial_grading);
  if (!(o.band_outer > o.band_inner) || o.band_factor == 1.0) return g;
  const double a = std::clamp(o.band_inner, r0, r1), b = std::clamp(o.band_outer, r0, r1), f = o.band_factor;
  // Integral of the density from r0 to r, and its inverse.
  const double total = (r1 - r0) + (f - 1.0) * (b - a);
  const double at_a = a - r0, at_b = at_a + f * (b - a);
  auto radius_at = [&](double c) {
    if (c <= at_a) return r0 + c;
    if (c <= at_b) return a + (c - at_a) / f;
    return b + (c - at_b);
  };
  std::vector<double> out(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) out[static_cast<std::size_t>(k)] = (radius_at(total * k / n) - r0) / (r1 - r0);
  out.front() = 0.0;
  out.back() = 1.0;
  return out;
}

// What every sub-sector shares: its angle, the kite and the node layers of the ring.
struct DiscLayout {
  int sectors = 0;      // sub-sectors of at most max_sector_deg
  double beta = 0.0;    // sub-sector angle [rad]
  int n = 0;            // elements along each kite side (2 n along the rim of a sub-sector)
  double rc = 0.0;      // core radius: the kite's corners on the sub-sector's edges
  double r_inner = 0.0; // where the transition ends: ring_start, or the rim
  int mt = 0;           // transition layers
  // Fractions s in [0, 1] of the transition layers from the kite's sides (0) to r_inner (1),
  // then the radii of the circular layers beyond ring_start (none without ring_start).
  std::vector<double> transition, radii;
  int layers_total = 0;  // mt + radii.size()
  // Coarsened centre (coarse_inside > 0): the core and the ring layers below fine_from have half
  // the elements along them (n / 2 per kite side); layer fine_from has the full count, its odd
  // nodes hanging in the middle of the coarse elements' outer edges. fine_from = 0: not coarsened.
  int fine_from = 0;
  int n_core = 0;  // elements along each kite side of the core
};

void check_disc_options(const DiscOptions& o) {
  if (!(o.radius > 0)) throw std::invalid_argument("radius must be > 0");
  if (!(o.angle_deg > 0 && o.angle_deg <= 360)) throw std::invalid_argument("angle must lie in (0, 360]");
  if (o.elements_per_45deg < 2) throw std::invalid_argument("elements_per_45deg must be >= 2");
  if (!(o.radial_grading > 0 && o.band_factor > 0)) throw std::invalid_argument("grading and band factor must be > 0");
  if (!(o.max_sector_deg == 45.0 || o.max_sector_deg == 90.0)) throw std::invalid_argument("max_sector_deg must be 45 or 90");
  if (!(o.coarse_inside >= 0.0 && o.coarse_inside < o.radius)) throw std::invalid_argument("coarse_inside must lie in [0, radius)");
}

// Radius of ring layer j along the sub-sector's first edge.
double layer_radius(const DiscLayout& l, int j) {
  return j <= l.mt ? l.rc + l.transition[static_cast<std::size_t>(j)] * (l.r_inner - l.rc) : l.radii[static_cast<std::size_t>(j - l.mt - 1)];
}

// The first ring layer at or beyond coarse_inside carries the hanging nodes; it must lie beyond
// the core and inside the rim (whose nodes are clamped).
void place_coarsening(const DiscOptions& o, DiscLayout& l) {
  l.n_core = l.n;
  if (o.coarse_inside <= 0.0) return;
  if (l.n % 2 != 0)
    throw std::invalid_argument("coarse_inside needs an even number of elements along each side of the core (" + std::to_string(l.n) +
                                "): elements_per_45deg a multiple of 4");
  int j = 0;
  while (j <= l.layers_total && layer_radius(l, j) < o.coarse_inside) ++j;
  if (j == 0 || j >= l.layers_total)
    throw std::invalid_argument("coarse_inside must lie between the core (" + std::to_string(l.rc) + " mm) and the last ring layer inside the rim (" +
                                std::to_string(layer_radius(l, l.layers_total - 1)) + " mm)");
  l.fine_from = j;
  l.n_core = l.n / 2;
}

DiscLayout disc_layout(const DiscOptions& o) {
  const double pi = std::numbers::pi;
  DiscLayout l;
  const int sectors = static_cast<int>(std::ceil(o.angle_deg / o.max_sector_deg - 1e-9));
  const double beta = o.angle_deg / sectors * pi / 180.0;  // sub-sector angle
  // Even number of rim elements per sub-sector: n per kite side.
  const int n = std::max(1, static_cast<int>(std::lround(o.elements_per_45deg * (beta * 180.0 / pi) / 45.0 / 2.0)));
  const double rim_h = o.radius * beta / (2 * n);
  // Core radius: the kite's sides have n elements of about the rim element size (default).
  const double rc = o.core_radius > 0 ? o.core_radius : std::min(0.6 * o.radius, n * rim_h * 1.2);
  if (!(rc < o.radius)) throw std::invalid_argument("core radius must be smaller than the radius");
  // Ring layers: (transition part) fractions from the kite's sides to the circle ring_start,
  // then (circular part) true radii. Without ring_start the whole ring is one transition to the
  // rim (the kite's sides blend into the rim arc).
  const bool circular = o.ring_start > 0.0;
  if (circular && !(o.ring_start > rc / std::cos(0.5 * beta) && o.ring_start < o.radius))
    throw std::invalid_argument("ring_start must lie beyond the core (" + std::to_string(rc / std::cos(0.5 * beta)) + " mm) and inside the radius");
  if (o.rim_ring_width < 0.0 || (o.rim_ring_width > 0.0 && !circular) ||
      (circular && !(o.rim_ring_width < o.radius - o.ring_start)))
    throw std::invalid_argument("rim_ring_width needs ring_start and must be smaller than radius - ring_start");
  const double r_spaced = o.radius - o.rim_ring_width;  // end of the spaced circular layers
  const int m_default = std::max(1, static_cast<int>(std::lround((o.radius - rc) / rim_h)));
  const int m = o.radial_elements > 0 ? o.radial_elements : m_default;
  l.mt = !circular ? m
         : o.transition_elements > 0
             ? o.transition_elements
             : std::max(1, static_cast<int>(std::lround((o.ring_start - rc) / (o.ring_start * beta / (2 * n)))));
  l.transition = circular ? graded_points(0.0, 1.0, l.mt, 1.0) : ring_layers(m, rc, o.radius, o);
  if (circular) {
    for (double s : ring_layers(m, o.ring_start, r_spaced, o)) l.radii.push_back(o.ring_start + s * (r_spaced - o.ring_start));
    l.radii.erase(l.radii.begin());
    if (o.rim_ring_width > 0.0) l.radii.push_back(o.radius);
    l.radii.back() = o.radius;
  }
  l.sectors = sectors;
  l.beta = beta;
  l.n = n;
  l.rc = rc;
  l.r_inner = circular ? o.ring_start : o.radius;
  l.layers_total = l.mt + static_cast<int>(l.radii.size());
  place_coarsening(o, l);
  return l;
}

int add_node(Mesh& mesh, const Eigen::Vector2d& p) {
  mesh.nodes.emplace_back(p.x(), p.y(), 0.0);
  return static_cast<int>(mesh.nodes.size()) - 1;
}

Eigen::Vector2d edge(const Eigen::Vector2d& p, const Eigen::Vector2d& q, double t) { return p + t * (q - p); }

// Core of a sub-sector: transfinite (Coons) patch on O -> A -> M -> B, parameters (u along OA,
// v along OB), n x n elements.
void add_core(Mesh& mesh, const Eigen::Vector2d& O, const Eigen::Vector2d& A, const Eigen::Vector2d& M,
              const Eigen::Vector2d& B, int n) {
  std::vector<int> core((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
      const Eigen::Vector2d bottom = edge(O, A, u), top = edge(B, M, u), left = edge(O, B, v), right = edge(A, M, v);
      const Eigen::Vector2d p = (1 - v) * bottom + v * top + (1 - u) * left + u * right -
                                ((1 - u) * (1 - v) * O + u * (1 - v) * A + u * v * M + (1 - u) * v * B);
      core[j * (n + 1) + i] = add_node(mesh, p);
    }
  }
  auto cid = [&](int i, int j) { return core[j * (n + 1) + i]; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) mesh.quads.push_back({cid(i, j), cid(i + 1, j), cid(i + 1, j + 1), cid(i, j + 1)});
  }
}

// Ring of the sub-sector starting at polar angle t0: inner polyline A -> M -> B, transition
// layers to r_inner, then the circular layers. A layer has 2 n segments, or 2 n_core below
// fine_from.
void add_ring(Mesh& mesh, const DiscLayout& l, double t0, const Eigen::Vector2d& A, const Eigen::Vector2d& M,
              const Eigen::Vector2d& B) {
  const int mt = l.mt, layers_total = l.layers_total;
  auto segments = [&](int j) { return 2 * (j < l.fine_from ? l.n_core : l.n); };
  auto position = [&](int j, int k) {
    const int half = segments(j) / 2;
    const Eigen::Vector2d in = k <= half ? edge(A, M, static_cast<double>(k) / half) : edge(M, B, static_cast<double>(k - half) / half);
    const double th = t0 + l.beta * k / segments(j);
    const Eigen::Vector2d dir(std::cos(th), std::sin(th));
    return j <= mt ? Eigen::Vector2d(in + l.transition[static_cast<std::size_t>(j)] * (l.r_inner * dir - in))
                   : Eigen::Vector2d(l.radii[static_cast<std::size_t>(j - mt - 1)] * dir);
  };
  std::vector<std::vector<int>> layer(static_cast<std::size_t>(layers_total) + 1);
  for (int j = 0; j <= layers_total; ++j) {
    auto& ids = layer[static_cast<std::size_t>(j)];
    ids.resize(static_cast<std::size_t>(segments(j)) + 1);
    const bool hanging = j == l.fine_from && l.fine_from > 0;
    for (int k = 0; k <= segments(j); ++k)
      if (!hanging || k % 2 == 0) ids[static_cast<std::size_t>(k)] = add_node(mesh, position(j, k));
    if (!hanging) continue;
    // The odd nodes halve the straight outer edges of the coarse elements below.
    for (int k = 1; k < segments(j); k += 2) {
      const int a = ids[static_cast<std::size_t>(k - 1)], b = ids[static_cast<std::size_t>(k + 1)];
      const Eigen::Vector3d mid = 0.5 * (mesh.nodes[static_cast<std::size_t>(a)] + mesh.nodes[static_cast<std::size_t>(b)]);
      ids[static_cast<std::size_t>(k)] = add_node(mesh, mid.head<2>());
      mesh.constrained_nodes.push_back({ids[static_cast<std::size_t>(k)], {{a, 0.5}, {b, 0.5}}});
    }
  }
  for (int j = 0; j < layers_total; ++j) {
    const auto& lo = layer[static_cast<std::size_t>(j)];
    const auto& hi = layer[static_cast<std::size_t>(j + 1)];
    const int step = static_cast<int>(hi.size() - 1) / static_cast<int>(lo.size() - 1);  // 2 below the hanging layer
    for (int k = 0; k + 1 < static_cast<int>(lo.size()); ++k)
      mesh.quads.push_back({lo[static_cast<std::size_t>(k)], hi[static_cast<std::size_t>(step * k)], hi[static_cast<std::size_t>(step * (k + 1))],
                            lo[static_cast<std::size_t>(k + 1)]});
  }
}

// Sub-sector s (polar angles s beta to (s + 1) beta): its core, then its ring. Neighbouring
// sub-sectors duplicate their shared edge's nodes (merged afterwards).
void add_sector(Mesh& mesh, const DiscLayout& l, int s) {
  const double rc = l.rc, beta = l.beta;
  const double t0 = s * beta;
  const Eigen::Vector2d O(0, 0), A = rc * Eigen::Vector2d(std::cos(t0), std::sin(t0)),
                        B = rc * Eigen::Vector2d(std::cos(t0 + beta), std::sin(t0 + beta));
  // Bisector point of a right-angled kite (A-M perpendicular to O-A): corner angles beta at
  // the axis, 90 deg at A and B, 180 deg - beta at M; a square for beta = 90 deg.
  const Eigen::Vector2d M = rc / std::cos(0.5 * beta) * Eigen::Vector2d(std::cos(t0 + 0.5 * beta), std::sin(t0 + 0.5 * beta));
  add_core(mesh, O, A, M, B, l.n_core);
  add_ring(mesh, l, t0, A, M, B);
}

// Element set "all"; node sets "axis", "rim" and, for a pie, its edges "edge_theta0" (along +x)
// and "edge_theta1" (at angle_deg).
void name_disc_sets(Mesh& mesh, const DiscOptions& o) {
  const double pi = std::numbers::pi;
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
}

}  // namespace

Mesh disc_mesh(const DiscOptions& o) {
  check_disc_options(o);
  const DiscLayout layout = disc_layout(o);
  Mesh mesh;
  for (int s = 0; s < layout.sectors; ++s) add_sector(mesh, layout, s);
  merge_coincident_nodes(mesh, 1e-9 * o.radius);
  name_disc_sets(mesh, o);
  return mesh;
}

}  // namespace spifit::mesh
