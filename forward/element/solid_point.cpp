#include "forward/element/solid_point.hpp"

#include "forward/io/binary_archive.hpp"

#include <Eigen/Cholesky>

#include <cmath>
#include <string>

namespace spifit::element {
namespace {
Voigt6 read_voigt(io::BinaryReader& r, const char* what) {
  const Eigen::VectorXd v = r.vector();
  if (v.size() != 6) throw io::ArchiveError(std::string("solid point ") + what + ": expected 6 components, found " + std::to_string(v.size()));
  return v;
}
}  // namespace

SolidPoint::SolidPoint(const Law& law) : point_(law), tangent_(law.elastic_matrix()), tangent_trial_(law.elastic_matrix()) {}

PointStatus admissible_green_strain(const Voigt6& green) {
  PointStatus status;
  // C = I + 2E positive definite: its leading principal minors.
  const double c11 = 1.0 + 2.0 * green(0), c22 = 1.0 + 2.0 * green(1), c33 = 1.0 + 2.0 * green(2);
  const double c12 = green(3), c13 = green(4), c23 = green(5);
  const double m2 = c11 * c22 - c12 * c12;
  const double det = c11 * (c22 * c33 - c23 * c23) - c12 * (c12 * c33 - c23 * c13) + c13 * (c12 * c23 - c22 * c13);
  if (!(c11 > 0.0 && m2 > 0.0 && det > 1e-12)) {
    status.ok = false;
    status.reason = std::isfinite(det) ? "element turned inside out (det C = " + std::to_string(det) + ")" : "non-finite strain";
    status.suggested_scale = 0.25;
  }
  return status;
}

PointStatus SolidPoint::update(const Voigt6& green, Voigt6* S, Voigt6x6* tangent) {
  const PointStatus admissible = admissible_green_strain(green);
  if (!admissible.ok) return admissible;
  const LogStrain3 ls = log_strain_3d(green);
  Voigt6 t;
  Voigt6x6 ct;
  const PointStatus status = update_log(ls.value, &t, &ct);
  if (!status.ok) return status;
  if (S) *S = ls.first.transpose() * t;
  if (tangent) *tangent = ls.first.transpose() * ct * ls.first + log_strain_3d_second(ls, t);
  return status;
}

PointStatus SolidPoint::update_log(const Voigt6& eps, Voigt6* T, Voigt6x6* tangent) {
  PointStatus status;
  eps_trial_ = eps;
  const Voigt6 d_eps = eps - eps_;
  Voigt6x6 ct;
  const material::UpdateResult r = point_.update(d_eps, &ct);
  if (!r.ok()) {
    status.ok = false;
    status.reason = r.reason;
    status.suggested_scale = r.suggested_scale;
    return status;
  }
  // Start of an increment (no strain change beyond round-off): the last converged consistent
  // tangent instead of the elastic one, as the shell's layers do.
  if (d_eps.cwiseAbs().maxCoeff() <= 1e-14 * (1.0 + eps_.cwiseAbs().maxCoeff())) ct = tangent_;
  tangent_trial_ = ct;
  if (T) *T = point_.trial().stress;
  if (tangent) *tangent = ct;
  return status;
}

void SolidPoint::commit() {
  point_.commit();
  eps_ = eps_trial_;
  tangent_ = tangent_trial_;
}

void SolidPoint::revert() {
  point_.revert();
  eps_trial_ = eps_;
  tangent_trial_ = tangent_;
}

double SolidPoint::elastic_energy_density() const {
  const Voigt6& t = point_.committed().stress;
  return 0.5 * t.dot(point_.law().elastic_matrix().ldlt().solve(t));
}

void SolidPoint::save_state(io::BinaryWriter& w) const {
  const State& s = point_.committed();
  w.vector(s.stress);
  w.vector(s.plastic_strain);
  w.vector(s.back_stress);
  w.f64(s.eqps);
  w.f64(s.plastic_work);
  w.vector(eps_);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) w.f64(tangent_(i, j));
}

void SolidPoint::load_state(io::BinaryReader& r) {
  State s;
  s.stress = read_voigt(r, "stress");
  s.plastic_strain = read_voigt(r, "plastic strain");
  s.back_stress = read_voigt(r, "back-stress");
  s.eqps = r.f64();
  s.plastic_work = r.f64();
  point_.set_committed(s);
  eps_ = eps_trial_ = read_voigt(r, "log strain");
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) tangent_(i, j) = r.f64();
  tangent_trial_ = tangent_;
}

}  // namespace spifit::element
