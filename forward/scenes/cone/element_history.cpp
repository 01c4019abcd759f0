#include "forward/scenes/cone/element_history.hpp"

#include "forward/model/shell_model.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace spifit::scene {
namespace {

// The initial polar frame at the element centre: unit normal n0 of the initial mid-surface,
// e_r (radial at the centroid's polar angle, projected on the tangent plane), e_theta = n0 x e_r.
struct CentreFrame {
  Eigen::Vector3d n0, er, et;
  Eigen::Vector3d A0, A1;  // initial tangents d X / d xi, d X / d eta at the centre
};

CentreFrame centre_frame(const element::NodeVectors& X) {
  CentreFrame f;
  const Eigen::Matrix<double, 2, 4> dn = element::quad_shape_derivatives(0.0, 0.0);
  f.A0 = element::combine(dn.row(0).transpose(), X);
  f.A1 = element::combine(dn.row(1).transpose(), X);
  f.n0 = f.A0.cross(f.A1).normalized();
  const Eigen::Vector3d c = element::combine(element::quad_shape(0.0, 0.0), X);
  const double size = std::sqrt(f.A0.cross(f.A1).norm());
  const double theta = c.head<2>().norm() > 1e-9 * size ? std::atan2(c.y(), c.x()) : 0.0;
  Eigen::Vector3d er(std::cos(theta), std::sin(theta), 0.0);
  er -= er.dot(f.n0) * f.n0;
  if (er.norm() < 1e-6) er = f.A0;  // radial direction normal to the element (not a sheet in the x-y plane)
  f.er = er.normalized();
  f.et = f.n0.cross(f.er);
  return f;
}

// (a, b) with a A0 + b A1 = v for a tangent vector v: the in-plane derivative along v is
// a d/dxi + b d/deta.
Eigen::Vector2d tangent_coefficients(const CentreFrame& f, const Eigen::Vector3d& v) {
  Eigen::Matrix2d g;
  g << f.A0.dot(f.A0), f.A0.dot(f.A1), f.A1.dot(f.A0), f.A1.dot(f.A1);
  return g.ldlt().solve(Eigen::Vector2d(f.A0.dot(v), f.A1.dot(v)));
}

}  // namespace

int nearest_element(const mesh::Mesh& m, double r, double theta_deg) {
  const double t = theta_deg * std::numbers::pi / 180.0;
  const Eigen::Vector2d p(r * std::cos(t), r * std::sin(t));
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int e = 0; e < m.num_elements(); ++e) {
    const double dist = (m.centroid(e).head<2>() - p).squaredNorm();
    if (dist < best_d) {
      best_d = dist;
      best = e;
    }
  }
  return best;
}

PolarStrains centre_polar_strains(const element::NodeVectors& X, const element::NodeVectors& D, const element::NodeVectors& x,
                                  const element::NodeVectors& d) {
  const CentreFrame f = centre_frame(X);
  const Eigen::Matrix<double, 2, 4> dn = element::quad_shape_derivatives(0.0, 0.0);
  const auto along = [&](const element::NodeVectors& v, const Eigen::Vector2d& ab) {
    return Eigen::Vector3d(ab(0) * element::combine(dn.row(0).transpose(), v) + ab(1) * element::combine(dn.row(1).transpose(), v));
  };
  const Eigen::Vector2d cr = tangent_coefficients(f, f.er), ct = tangent_coefficients(f, f.et);
  const Eigen::Vector3d fr = along(x, cr), ft = along(x, ct);    // F e_r, F e_theta
  const Eigen::Vector3d dr = along(d, cr), dt = along(d, ct);    // current director derivatives
  const Eigen::Vector3d Dr = along(D, cr), Dt = along(D, ct);    // initial ones
  PolarStrains s;
  s.membrane << 0.5 * (fr.squaredNorm() - 1.0), 0.5 * (ft.squaredNorm() - 1.0), fr.dot(ft);
  s.bending << fr.dot(dr) - f.er.dot(Dr), ft.dot(dt) - f.et.dot(Dt), fr.dot(dt) + ft.dot(dr) - f.er.dot(Dt) - f.et.dot(Dr);
  s.stretch_r = fr.norm();
  s.stretch_theta = ft.norm();
  return s;
}

Eigen::Vector3d rotate_tensor_components(const Eigen::Vector3d& s12, double c, double s) {
  return {c * c * s12(0) + s * s * s12(1) + 2.0 * c * s * s12(2), s * s * s12(0) + c * c * s12(1) - 2.0 * c * s * s12(2),
          -c * s * s12(0) + c * s * s12(1) + (c * c - s * s) * s12(2)};
}

double von_mises_plane_stress(const Eigen::Vector3d& s) {
  return std::sqrt(std::max(0.0, s(0) * s(0) - s(0) * s(1) + s(1) * s(1) + 3.0 * s(2) * s(2)));
}

ElementHistoryRow element_history_row(const model::ShellModel& model, int e, const element::ThicknessRule& rule) {
  const Eigen::Vector3d& material_axis = model.material_axis(e);
  const auto& q = model.mesh().quads.at(static_cast<std::size_t>(e));
  element::NodeVectors X, D, x, d;
  for (std::size_t i = 0; i < 4; ++i) {
    const int n = q[i];
    X[i] = model.mesh().nodes[static_cast<std::size_t>(n)];
    D[i] = model.reference_director(n);
    x[i] = model.position(n);
    d[i] = model.director(n);
  }
  const element::ShellQ4& el = model.element(e);
  const int layers = el.section(0).layers();
  if (static_cast<int>(rule.zeta.size()) != layers)
    throw std::invalid_argument("element history: the thickness rule has " + std::to_string(rule.zeta.size()) + " points, the element " +
                                std::to_string(layers));
  ElementHistoryRow row;
  row.centre = centre_polar_strains(X, D, x, d);
  const double share = 1.0 / el.points();
  for (int p = 0; p < el.points(); ++p) row.thickness += share * el.section(p).thickness();
  // Material frame (ShellQ4: rolling direction projected on the initial tangent plane; the
  // element's xi direction if the rolling direction is almost normal to it).
  const CentreFrame f = centre_frame(X);
  Eigen::Vector3d m1 = material_axis - material_axis.dot(f.n0) * f.n0;
  if (m1.norm() < 0.1) m1 = f.A0 - f.A0.dot(f.n0) * f.n0;
  m1.normalize();
  const Eigen::Vector3d m2 = f.n0.cross(m1);
  const double c = m1.dot(f.er), s = m2.dot(f.er);
  double weight = 0.0;
  for (int l = 0; l < layers; ++l) {
    LayerHistory h;
    h.zeta = rule.zeta[static_cast<std::size_t>(l)];
    h.strain = row.centre.membrane + h.zeta * 0.5 * row.thickness * row.centre.bending;
    Eigen::Vector3d stress = Eigen::Vector3d::Zero();
    for (int p = 0; p < el.points(); ++p) {
      const auto& st = el.section(p).layer_state(l);
      stress += share * st.stress;
      h.eqps += share * st.eqps;
    }
    h.stress = rotate_tensor_components(stress, c, s);
    h.von_mises = von_mises_plane_stress(h.stress);
    row.von_mises_mean += rule.weight[static_cast<std::size_t>(l)] * h.von_mises;
    weight += rule.weight[static_cast<std::size_t>(l)];
    row.layers.push_back(h);
  }
  row.von_mises_mean /= weight;
  return row;
}

std::vector<std::string> element_history_columns(int layers) {
  std::vector<std::string> c{"travel [mm]", "lambda",     "thickness [mm]", "lambda_r",    "lambda_theta",   "E_rr",
                             "E_tt",        "gamma_rt",   "K_rr [1/mm]",    "K_tt [1/mm]", "K_rt [1/mm]",    "S_vm_mean [MPa]"};
  for (int l = 1; l <= layers; ++l) {
    std::string p = "L";  // (not "L" + ...: GCC 12 warns falsely, -Wrestrict)
    p += std::to_string(l);
    p += '_';
    for (const char* name : {"zeta", "E_rr", "E_tt", "gamma_rt", "S_rr [MPa]", "S_tt [MPa]", "S_rt [MPa]", "S_vm [MPa]", "eqps"})
      c.push_back(p + name);
  }
  return c;
}

std::vector<double> element_history_values(double travel, double lambda, const ElementHistoryRow& row) {
  const auto& m = row.centre.membrane;
  const auto& k = row.centre.bending;
  std::vector<double> v{travel, lambda, row.thickness, row.centre.stretch_r, row.centre.stretch_theta, m(0), m(1), m(2), k(0), k(1), k(2),
                        row.von_mises_mean};
  for (const auto& h : row.layers)
    v.insert(v.end(), {h.zeta, h.strain(0), h.strain(1), h.strain(2), h.stress(0), h.stress(1), h.stress(2), h.von_mises, h.eqps});
  return v;
}

}  // namespace spifit::scene
