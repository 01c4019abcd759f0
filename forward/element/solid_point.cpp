#include "forward/element/solid_point.hpp"

#include "forward/io/binary_archive.hpp"

#include <Eigen/Cholesky>

#include <cmath>
#include <stdexcept>
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
  const PointStatus status = integrate(ls.value, &t, &ct, tangent != nullptr);
  if (!status.ok) return status;
  if (S) *S = ls.first.transpose() * t;
  if (tangent) *tangent = ls.first.transpose() * ct * ls.first + log_strain_3d_second(ls, t);
  return status;
}

PointStatus SolidPoint::update_log(const Voigt6& eps, Voigt6* T, Voigt6x6* tangent) { return integrate(eps, T, tangent, tangent != nullptr); }

PointStatus SolidPoint::integrate(const Voigt6& eps, Voigt6* T, Voigt6x6* tangent, bool tangent_wanted) {
  PointStatus status;
  tangent_exact_ = true;
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
  // tangent instead of the elastic one, as the shell's layers do (not for exact tangents).
  if (d_eps.cwiseAbs().maxCoeff() <= 1e-14 * (1.0 + eps_.cwiseAbs().maxCoeff())) {
    tangent_trial_ = tangent_;
    if (!exact_tangents_) {
      if (tangent_wanted && ct != tangent_) tangent_exact_ = false;
      ct = tangent_;
    }
  } else {
    tangent_trial_ = ct;
  }
  if (T) *T = point_.trial().stress;
  if (tangent) *tangent = ct;
  return status;
}

void SolidPoint::commit() {
  point_.commit();
  eps_ = eps_trial_;
  tangent_ = tangent_trial_;
  if (sensitivities_) d_ = d_trial_;
}

void SolidPoint::revert() {
  point_.revert();
  eps_trial_ = eps_;
  tangent_trial_ = tangent_;
  if (sensitivities_) d_trial_ = d_;
}

void SolidPoint::enable_sensitivities(bool tangent_derivatives) {
  sensitivities_ = true;
  tangent_derivatives_ = tangent_derivatives;
  d_ = d_trial_ = SolidPointDerivatives();
}

SolidSensitivityLaw::SolidSensitivityLaw(const material::MaterialParams<material::SensitivityScalar>& law, const material::ReturnMappingOptions& options,
                                         int count)
    : full(law, options) {
  if (material::seeded_beyond(law, count))
    throw std::logic_error("SolidSensitivityLaw: the law is seeded beyond its " + std::to_string(count) + " parameters' slots");
  if (count <= 2) two = std::make_unique<const TwoSlotLaw6>(material::narrowed_params<2>(law), options);
  else if (count <= 4) four = std::make_unique<const FourSlotLaw6>(material::narrowed_params<4>(law), options);
}

PointStatus SolidPoint::sensitivities(const SolidSensitivityLaw& law, const Voigt6& eps, const SensColumns6* deps, Voigt6S* T) {
  if (!sensitivities_) throw std::logic_error("SolidPoint::sensitivities before enable_sensitivities");
  if (law.two) return sensitivities_on<2>(*law.two, eps, deps, T);
  if (law.four) return sensitivities_on<4>(*law.four, eps, deps, T);
  return sensitivities_on<material::kSensitivitySlots>(law.full, eps, deps, T);
}

template <int N>
PointStatus SolidPoint::sensitivities_on(const material::ReturnMapping<ceres::Jet<double, N>, 6>& law, const Voigt6& eps, const SensColumns6* deps,
                                         Voigt6S* T) {
  using J = ceres::Jet<double, N>;
  // Slot k of a value with the rows' derivatives, and back with the slots beyond N zero.
  const auto jet = [](double v, const material::SensitivityRow& d) { return material::narrowed<N>(material::with_derivatives(v, d)); };
  const auto row = [](const J& x) { return material::derivatives_of(material::widened<N>(x)); };
  // The committed state with its derivatives; the flow stress as a value (the law reads it for
  // the elastic check alone).
  const State& c = point_.committed();
  material::MaterialState<J, 6> s0, s1;
  for (int i = 0; i < 6; ++i) {
    s0.stress(i) = jet(c.stress(i), d_.stress.row(i));
    s0.plastic_strain(i) = jet(c.plastic_strain(i), d_.plastic_strain.row(i));
    s0.back_stress(i) = jet(c.back_stress(i), d_.back_stress.row(i));
  }
  s0.eqps = jet(c.eqps, d_.eqps);
  s0.plastic_work = jet(c.plastic_work, d_.plastic_work);
  s0.flow_stress = J(c.flow_stress);
  // The increment as update_log forms it, value for value.
  const Voigt6 d_eps_value = eps - eps_;
  Eigen::Matrix<J, 6, 1> d_eps;
  for (int i = 0; i < 6; ++i) {
    material::SensitivityRow d = -d_.log_strain.row(i);
    if (deps) d += deps->row(i);
    d_eps(i) = jet(d_eps_value(i), d);
  }
  Eigen::Matrix<J, 6, 6> ct;
  const bool with_tangent = deps && tangent_derivatives_;
  const material::UpdateResult r = law.integrate(s0, d_eps, s1, with_tangent ? &ct : nullptr);
  PointStatus status;
  if (!r.ok()) {
    status.ok = false;
    status.reason = r.reason;
    status.suggested_scale = r.suggested_scale;
    return status;
  }
  if (T)
    for (int i = 0; i < 6; ++i) (*T)(i) = material::widened<N>(s1.stress(i));
  if (deps) {
    for (int i = 0; i < 6; ++i) {
      d_trial_.stress.row(i) = row(s1.stress(i));
      d_trial_.plastic_strain.row(i) = row(s1.plastic_strain(i));
      d_trial_.back_stress.row(i) = row(s1.back_stress(i));
    }
    d_trial_.eqps = row(s1.eqps);
    d_trial_.plastic_work = row(s1.plastic_work);
    d_trial_.log_strain = *deps;
    // update_log's choice of tangent: the committed one where the strain did not move.
    if (with_tangent) {
      if (d_eps_value.cwiseAbs().maxCoeff() <= 1e-14 * (1.0 + eps_.cwiseAbs().maxCoeff())) {
        d_trial_.tangent = d_.tangent;
      } else {
        for (int j = 0; j < 6; ++j)
          for (int i = 0; i < 6; ++i) d_trial_.tangent.row(6 * j + i) = row(ct(i, j));
      }
    }
  }
  return status;
}

void save_columns(io::BinaryWriter& w, const Eigen::MatrixXd& m, int count) { w.matrix(m.leftCols(count)); }

Eigen::MatrixXd read_columns(io::BinaryReader& r, const char* what, int rows, int count) {
  Eigen::MatrixXd v = r.matrix();
  if (v.rows() != rows || v.cols() != count)
    throw io::ArchiveError(std::string(what) + " derivatives: expected " + std::to_string(rows) + " x " + std::to_string(count) + ", found " +
                           std::to_string(v.rows()) + " x " + std::to_string(v.cols()));
  return v;
}

void SolidPoint::save_sensitivities(io::BinaryWriter& w, int count) const {
  for (const Eigen::MatrixXd& m : {Eigen::MatrixXd(d_.stress), Eigen::MatrixXd(d_.plastic_strain), Eigen::MatrixXd(d_.back_stress),
                                   Eigen::MatrixXd(d_.log_strain), Eigen::MatrixXd(d_.eqps), Eigen::MatrixXd(d_.plastic_work)})
    save_columns(w, m, count);
  if (tangent_derivatives_) save_columns(w, d_.tangent, count);
}

void SolidPoint::load_sensitivities(io::BinaryReader& r, int count) {
  if (!sensitivities_) throw std::logic_error("SolidPoint::load_sensitivities before enable_sensitivities");
  load_columns(r, "solid point stress", count, &d_.stress);
  load_columns(r, "solid point plastic strain", count, &d_.plastic_strain);
  load_columns(r, "solid point back-stress", count, &d_.back_stress);
  load_columns(r, "solid point log strain", count, &d_.log_strain);
  load_columns(r, "solid point eqps", count, &d_.eqps);
  load_columns(r, "solid point plastic work", count, &d_.plastic_work);
  if (tangent_derivatives_) load_columns(r, "solid point tangent", count, &d_.tangent);
  d_trial_ = d_;
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
