#include "forward/mesh/benchmark_meshes.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace spifit::mesh {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

// Structured (nu + 1) x (nv + 1) grid of point(u, v), u = i / nu and v = j / nv in [0, 1];
// node i + (nu + 1) j, quads counter-clockwise in (i, j), element set "all".
template <class F>
Mesh structured_grid(int nu, int nv, F point) {
  Mesh m;
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i)
      m.nodes.push_back(point(static_cast<double>(i) / nu, static_cast<double>(j) / nv));
  }
  auto id = [nu](int i, int j) { return i + (nu + 1) * j; };
  auto& all = m.element_sets["all"];
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      all.push_back(static_cast<int>(m.quads.size()));
      m.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return m;
}

// Grid nodes of the column i (all j) and of the row j (all i); ascending.
std::vector<int> column(int nu, int nv, int i) {
  std::vector<int> s;
  for (int j = 0; j <= nv; ++j) s.push_back(i + (nu + 1) * j);
  return s;
}
std::vector<int> row(int nu, int j) {
  std::vector<int> s;
  for (int i = 0; i <= nu; ++i) s.push_back(i + (nu + 1) * j);
  return s;
}

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(what);
}
}  // namespace

Mesh cylinder_roof_quarter(double radius, double length_half, double angle_deg, int n) {
  require(radius > 0 && length_half > 0, "roof radius and length must be > 0");
  require(angle_deg > 0 && angle_deg <= 180, "roof angle must be in (0, 180] deg");
  require(n >= 1, "element count must be >= 1");
  const double angle = angle_deg * kDeg;
  // u along the axis, v along the arc: d/du x d/dv = (1,0,0) x (0, cos, -sin) = radial outward.
  Mesh m = structured_grid(n, n, [&](double u, double v) {
    const double x = u * length_half, t = v * angle;
    return Eigen::Vector3d(x, radius * std::sin(t), radius * std::cos(t));
  });
  m.node_sets["symmetry_x0"] = column(n, n, 0);
  m.node_sets["diaphragm"] = column(n, n, n);
  m.node_sets["symmetry_crown"] = row(n, 0);
  m.node_sets["free_edge"] = row(n, n);
  m.node_sets["point_A"] = {(n + 1) * n};  // i = 0 (x = 0), j = n (theta = angle)
  return m;
}

Mesh hemisphere_quarter(double radius, double hole_deg, int n) {
  require(radius > 0, "sphere radius must be > 0");
  require(hole_deg > 0 && hole_deg < 90, "hole angle must be in (0, 90) deg");
  require(n >= 1, "element count must be >= 1");
  const double hole = hole_deg * kDeg, half_pi = 0.5 * std::numbers::pi;
  // u: azimuth phi 0..90 deg; v: from the equator (colatitude 90 deg) up to the hole edge. The
  // colatitude decreases with v, so e_phi x (-e_colatitude) = e_r: normals point outward.
  Mesh m = structured_grid(n, n, [&](double u, double v) {
    const double phi = u * half_pi, a = half_pi - v * (half_pi - hole);
    return Eigen::Vector3d(radius * std::sin(a) * std::cos(phi), radius * std::sin(a) * std::sin(phi),
                           radius * std::cos(a));
  });
  for (int j = 0; j <= n; ++j) m.nodes[(n + 1) * j + n].x() = 0.0;  // exact plane x = 0 (cos 90 deg)
  for (int i = 0; i <= n; ++i) m.nodes[i].z() = 0.0;                // exact equator (cos 90 deg)
  m.node_sets["symmetry_xz"] = column(n, n, 0);
  m.node_sets["symmetry_yz"] = column(n, n, n);
  m.node_sets["equator"] = row(n, 0);
  m.node_sets["hole"] = row(n, n);
  m.node_sets["load_x"] = {0};
  m.node_sets["load_y"] = {n};
  return m;
}

Mesh twisted_beam(double length, double width, double twist_deg, int nl, int nw) {
  require(length > 0 && width > 0, "beam length and width must be > 0");
  require(std::isfinite(twist_deg), "twist angle must be finite");
  require(nl >= 1 && nw >= 1, "element counts must be >= 1");
  require(nw % 2 == 0, "twisted beam needs an even element count across the width (tip_centre)");
  // u along x, v across the width: the normal is +z at the clamped end, turning with the twist.
  Mesh m = structured_grid(nl, nw, [&](double u, double v) {
    const double beta = u * twist_deg * kDeg, s = (v - 0.5) * width;
    return Eigen::Vector3d(u * length, s * std::cos(beta), s * std::sin(beta));
  });
  m.node_sets["clamped"] = column(nl, nw, 0);
  m.node_sets["tip"] = column(nl, nw, nl);
  m.node_sets["tip_centre"] = {nl + (nl + 1) * (nw / 2)};  // v = 1/2 exactly: s = 0
  return m;
}

Mesh strip(double length, double width, int nl, int nw) {
  require(length > 0 && width > 0, "strip length and width must be > 0");
  require(nl >= 1 && nw >= 1, "element counts must be >= 1");
  Mesh m = structured_grid(nl, nw, [&](double u, double v) {
    return Eigen::Vector3d(u * length, (v - 0.5) * width, 0.0);
  });
  m.node_sets["clamped"] = column(nl, nw, 0);
  m.node_sets["tip"] = column(nl, nw, nl);
  m.node_sets["edge_ymin"] = row(nl, 0);
  m.node_sets["edge_ymax"] = row(nl, nw);
  if (nw % 2 == 0) m.node_sets["tip_centre"] = {nl + (nl + 1) * (nw / 2)};
  return m;
}

}  // namespace spifit::mesh
