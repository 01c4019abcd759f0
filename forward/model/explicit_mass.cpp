#include "forward/model/explicit_mass.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/model/bulk_viscosity.hpp"
#include "forward/model/rotation_frames.hpp"
#include "forward/model/shell_model.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace spifit::model {
namespace {

// Largest frequency squared of element e: its tangent on the 5 non-drilling DOFs per node over
// its own lumped mass (translational m, rotational inertia i per node).
double element_omega_squared(ShellModel& model, int e, double m, double i) {
  Eigen::VectorXd re;
  Eigen::MatrixXd ke;
  const solver::ElementEvaluation ev = model.evaluate_element(e, &re, &ke);
  if (!ev.ok) throw std::invalid_argument("explicit mass: " + ev.where + ": " + ev.reason);
  const auto& q = model.mesh().quads[static_cast<std::size_t>(e)];
  Eigen::Matrix<double, 24, 20> p = Eigen::Matrix<double, 24, 20>::Zero();
  for (int a = 0; a < 4; ++a) {
    const int n = q[static_cast<std::size_t>(a)];
    p.block<3, 3>(6 * a, 5 * a).setIdentity();
    if (model.has_rotation_frame(n)) {
      p.block<2, 2>(6 * a + 3, 5 * a + 3).setIdentity();  // frame components t1, t2; the third is the normal
    } else {
      // The rotations that bend: about two axes normal to the director (the third is drilling).
      const Eigen::Vector3d& d = model.director(n);
      const Eigen::Vector3d t1 = least_aligned_normal(d);
      p.block<3, 1>(6 * a + 3, 5 * a + 3) = t1;
      p.block<3, 1>(6 * a + 3, 5 * a + 4) = d.cross(t1);
    }
  }
  Eigen::Matrix<double, 20, 20> k = p.transpose() * ke * p;
  Eigen::Matrix<double, 20, 1> w;
  for (int a = 0; a < 4; ++a) {
    w.segment<3>(5 * a).setConstant(1.0 / std::sqrt(m));
    w.segment<2>(5 * a + 3).setConstant(1.0 / std::sqrt(i));
  }
  const Eigen::Matrix<double, 20, 20> s = w.asDiagonal() * (0.5 * (k + k.transpose())) * w.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 20, 20>> eig(s, Eigen::EigenvaluesOnly);
  return std::max(0.0, eig.eigenvalues().maxCoeff());
}

}  // namespace

double element_length(const ShellModel& model, int e) {
  const auto& q = model.mesh().quads[static_cast<std::size_t>(e)];
  element::NodeVectors x;
  for (std::size_t a = 0; a < 4; ++a) x[a] = model.position(q[a]);
  return characteristic_length(x, diagonal_area(x));
}

std::string describe_element(const ShellModel& model, int e) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int n : model.mesh().quads[static_cast<std::size_t>(e)]) c += 0.25 * model.position(n);
  char buf[160];
  std::snprintf(buf, sizeof buf, "element %d (centre %.4g, %.4g, %.4g mm; length %.4g mm, thickness %.4g mm)", e, c.x(), c.y(), c.z(),
                element_length(model, e), model.element_thickness(e));
  return buf;
}

ExplicitMass explicit_mass(ShellModel& model, const ExplicitMassInputs& in) {
  if (!(in.density > 0.0 && std::isfinite(in.density))) throw std::invalid_argument("explicit mass: density must be > 0");
  if (const std::string why = in.options.validate(); !why.empty()) throw std::invalid_argument("explicit scheme: " + why);
  const solver::ExplicitOptions& o = in.options;
  const int ne = model.num_elements();
  ExplicitMass out;
  out.diagonal = Eigen::VectorXd::Zero(model.num_dofs());
  out.element_step.assign(static_cast<std::size_t>(ne), 0.0);
  out.element_length.assign(static_cast<std::size_t>(ne), 0.0);
  out.element_factor.assign(static_cast<std::size_t>(ne), o.mass_scaling);
  std::vector<double> unscaled(static_cast<std::size_t>(ne), 0.0);
  const double t = model.initial_thickness();
  model.revert();  // evaluate at the committed state
  for (int e = 0; e < ne; ++e) {
    const double area = model.element(e).reference_area();
    const double m = in.density * t * area / 4.0;                                       // eq. 6.61, per node
    const double i = o.rotational_scaling * m * std::max(t * t / 12.0, area / 18.0);    // eq. 6.62
    const double omega2 = element_omega_squared(model, e, m, i) + in.contact_stiffness / (in.density * t);
    // The bulk viscosity's linear term damps the highest mode by the fraction b1 of critical.
    unscaled[static_cast<std::size_t>(e)] =
        omega2 > 0.0 ? 2.0 / std::sqrt(omega2) * damped_step_fraction(o.bulk_viscosity_linear) : std::numeric_limits<double>::infinity();
    out.element_length[static_cast<std::size_t>(e)] = element_length(model, e);
  }
  model.revert();
  double smallest = std::numeric_limits<double>::infinity();
  for (int e = 0; e < ne; ++e) {
    const auto k = static_cast<std::size_t>(e);
    double f = o.mass_scaling;
    const double step = unscaled[k] * std::sqrt(f);
    if (o.target_time_step > 0.0 && step < o.target_time_step) {
      f *= (o.target_time_step / step) * (o.target_time_step / step);
      ++out.scaled_elements;
    }
    out.element_factor[k] = f;
    out.element_step[k] = unscaled[k] * std::sqrt(f);
    if (out.element_step[k] < smallest) {
      smallest = out.element_step[k];
      out.smallest_element = e;
    }
    const double area = model.element(e).reference_area();
    const double m = in.density * t * area / 4.0;
    const double i = o.rotational_scaling * m * std::max(t * t / 12.0, area / 18.0);
    out.mass += 4.0 * m;
    out.added_mass += 4.0 * m * (f - 1.0);
    for (int n : model.mesh().quads[k]) {
      for (int c = 0; c < 3; ++c) out.diagonal(ShellModel::dof(n, c)) += f * m;
      for (int c = 3; c < 6; ++c) out.diagonal(ShellModel::dof(n, c)) += f * i;
    }
  }
  out.smallest_unscaled_step = unscaled[static_cast<std::size_t>(out.smallest_element)];
  out.time_step = o.safety * smallest;
  return out;
}

double current_time_step(const ShellModel& model, const ExplicitMass& mass, double safety, const BulkViscosity* viscosity) {
  double step = std::numeric_limits<double>::infinity();
  for (int e = 0; e < model.num_elements(); ++e) {
    const auto k = static_cast<std::size_t>(e);
    const double fraction = viscosity ? viscosity->compression_fraction(e) : 1.0;
    step = std::min(step, mass.element_step[k] * fraction * element_length(model, e) / mass.element_length[k]);
  }
  return safety * step;
}

void save_explicit_mass(io::BinaryWriter& w, const ExplicitMass& mass) {
  w.section("explicit_mass");
  w.vector(mass.diagonal);
  w.f64s(mass.element_step);
  w.f64s(mass.element_length);
  w.f64s(mass.element_factor);
  for (double x : {mass.time_step, mass.smallest_unscaled_step, mass.mass, mass.added_mass}) w.f64(x);
  w.i64(mass.smallest_element);
  w.i64(mass.scaled_elements);
}

ExplicitMass load_explicit_mass(io::BinaryReader& r, int num_dofs, int num_elements) {
  r.section("explicit_mass");
  ExplicitMass m;
  m.diagonal = r.vector();
  m.element_step = r.f64s();
  m.element_length = r.f64s();
  m.element_factor = r.f64s();
  m.time_step = r.f64();
  m.smallest_unscaled_step = r.f64();
  m.mass = r.f64();
  m.added_mass = r.f64();
  const std::int64_t smallest = r.i64(), scaled = r.i64();
  const auto ne = static_cast<std::size_t>(num_elements);
  if (m.diagonal.size() != num_dofs || m.element_step.size() != ne || m.element_length.size() != ne || m.element_factor.size() != ne)
    throw io::ArchiveError("explicit mass of another model size");
  if (smallest < 0 || smallest >= num_elements || scaled < 0 || scaled > num_elements)
    throw io::ArchiveError("explicit mass: invalid element index or count");
  m.smallest_element = static_cast<int>(smallest);
  m.scaled_elements = static_cast<int>(scaled);
  return m;
}

}  // namespace spifit::model
