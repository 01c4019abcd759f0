#include "forward/element/shell_section.hpp"

#include "forward/element/log_strain.hpp"
#include "forward/io/binary_archive.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spifit::element {

ShellSection::ShellSection(const Law& law, const ThicknessRule& rule, double thickness0)
    : rule_(&rule), h0_(thickness0), h_(thickness0), compliance_(law.elastic_matrix().inverse()),
      points_(rule.zeta.size(), material::MaterialPoint<double, 3>(law)),
      eps_(rule.zeta.size(), Vec3::Zero()), eps_trial_(rule.zeta.size(), Vec3::Zero()),
      tangent_(rule.zeta.size(), law.elastic_matrix()), tangent_trial_(rule.zeta.size(), law.elastic_matrix()) {}

SectionStatus ShellSection::update(const Vec3& e, const Vec3& kappa, Vec6* resultant, Mat6* tangent) {
  SectionStatus status;
  e_trial_ = e;
  kappa_trial_ = kappa;
  tangent_exact_ = true;
  if (resultant) resultant->setZero();
  if (tangent) tangent->setZero();
  {
    const double c11 = 1.0 + 2.0 * e(0), c22 = 1.0 + 2.0 * e(1);
    const double det = c11 * c22 - e(2) * e(2);
    if (!(det > 1e-12 && c11 > 0.0 && c22 > 0.0)) {
      status.ok = false;
      status.reason = std::isfinite(det) ? "mid-surface stretched to a non-positive metric (det C = " + std::to_string(det) + ")"
                                         : "non-finite strain";
      status.suggested_scale = 0.25;
      return status;
    }
  }
  for (std::size_t l = 0; l < points_.size(); ++l) {
    const double z = rule_->zeta[l] * 0.5 * h_;
    const double w = rule_->weight[l] * 0.5 * h0_;
    const Vec3 green = e + z * kappa;
    const double c11 = 1.0 + 2.0 * green(0), c22 = 1.0 + 2.0 * green(1);
    const double det = c11 * c22 - green(2) * green(2);
    if (!(det > 1e-12 && c11 > 0.0 && c22 > 0.0)) {
      status.ok = false;
      status.layer = static_cast<int>(l);
      status.reason = std::isfinite(det) ? "layer stretched to a non-positive metric (det C = " + std::to_string(det) + ")"
                                         : "non-finite strain";
      status.suggested_scale = 0.25;
      return status;
    }
    const LogStrain ls = log_strain_with_derivatives(green, tangent != nullptr);
    eps_trial_[l] = ls.value;
    Eigen::Matrix3d ct;
    const Vec3 d_eps = ls.value - eps_[l];
    // The consistent tangent even for a residual alone: commit() keeps it for the next
    // increment's start (below), so a converged iterate assembled without the element tangent
    // (NewtonSolver::increment) leaves the same state as one assembled with it.
    const bool with_ct = keep_tangents_ || tangent != nullptr;
    const material::UpdateResult r = points_[l].update(d_eps, with_ct ? &ct : nullptr);
    if (!r.ok()) {
      status.ok = false;
      status.layer = static_cast<int>(l);
      status.reason = r.reason;
      status.suggested_scale = r.suggested_scale;
      return status;
    }
    // Start of an increment (no strain change beyond round-off): the last converged
    // consistent tangent instead of the elastic one, for Newton (not for exact tangents).
    if (with_ct) {
      const bool at_rest = d_eps.cwiseAbs().maxCoeff() <= 1e-14 * (1.0 + eps_[l].cwiseAbs().maxCoeff());
      tangent_trial_[l] = at_rest ? tangent_[l] : ct;
      if (at_rest && !exact_tangents_) {
        if (tangent && ct != tangent_[l]) tangent_exact_ = false;
        ct = tangent_[l];
      }
    }
    const Vec3& t = points_[l].trial().stress;
    const Vec3 s = ls.first.transpose() * t;
    if (resultant) {
      resultant->head<3>() += w * s;
      resultant->tail<3>() += (w * z) * s;
    }
    if (tangent) {
      Eigen::Matrix3d ds = ls.first.transpose() * ct * ls.first;
      for (int i = 0; i < 3; ++i) ds += t(i) * ls.second[static_cast<std::size_t>(i)];
      tangent->topLeftCorner<3, 3>() += w * ds;
      tangent->topRightCorner<3, 3>() += (w * z) * ds;
      tangent->bottomLeftCorner<3, 3>() += (w * z) * ds;
      tangent->bottomRightCorner<3, 3>() += (w * z * z) * ds;
    }
  }
  return status;
}

void ShellSection::enable_sensitivities(int slots) {
  if (slots < 1 || slots > material::kSensitivitySlots) throw std::logic_error("ShellSection::enable_sensitivities: 1 to 8 slots");
  sens_ = LayerDerivatives(layers(), slots);
  sens_trial_ = sens_;
  linear_ = LayerDerivatives();
  dh_.setZero();
  sens_trial_set_ = false;
  linear_count_ = -1;
}

SectionStatus ShellSection::update_sensitivities(const SensLaw& law, const Vec3S& e, const Vec3S& kappa, Vec6S* resultant) {
  const SectionStatus status = integrate_sensitivities(law, e, kappa, -1, resultant);
  if (!status.ok) return status;
  e_sens_ = e;
  kappa_sens_ = kappa;
  sens_trial_set_ = true;
  linear_count_ = -1;
  return status;
}

NarrowLaws::NarrowLaws(const material::MaterialParams<Sens>& law, const material::ReturnMappingOptions& options, int count) {
  // The narrow Jets keep the first slots only: the parameters must leave the others empty.
  if (material::seeded_beyond(law, count)) throw std::logic_error("NarrowLaws: the law is seeded beyond its " + std::to_string(count) + " parameters' slots");
  if (count + 3 <= 4)
    four = std::make_unique<FourSlotLaw>(material::narrowed_params<4>(law), options);
  else if (count + 3 <= 6)
    six = std::make_unique<SixSlotLaw>(material::narrowed_params<6>(law), options);
}

SectionStatus ShellSection::pseudo_resultants(const SensLaw& law, const NarrowLaws* narrow, const Vec3& e, const Vec3& kappa, int count, Vec6S* resultant) {
  if (count < 0 || count + 3 > material::kSensitivitySlots) throw std::logic_error("ShellSection::pseudo_resultants: no room for the strain's slots");
  if (!sensitivities_enabled()) throw std::logic_error("ShellSection::pseudo_resultants before enable_sensitivities");
  if (count > sens_.slots()) throw std::logic_error("ShellSection::pseudo_resultants: more parameters than slots enabled");
  if (linear_.slots() != count + 3) linear_ = LayerDerivatives(layers(), count + 3);
  const Vec3S es = e.cast<Sens>(), ks = kappa.cast<Sens>();
  const SectionStatus status = narrow && narrow->four && count + 3 <= 4  ? integrate_layers(*narrow->four, es, ks, count, resultant)
                               : narrow && narrow->six && count + 3 <= 6 ? integrate_layers(*narrow->six, es, ks, count, resultant)
                                                                         : integrate_sensitivities(law, es, ks, count, resultant);
  sens_trial_set_ = false;  // the linearisation is not a trial state: advance_sensitivities() makes one
  linear_count_ = status.ok ? count : -1;
  for (int i = 0; i < 6; ++i) (*resultant)(i).v.tail(material::kSensitivitySlots - count).setZero();
  return status;
}

void ShellSection::advance_sensitivities(const Vec3S& e, const Vec3S& kappa) {
  if (linear_count_ < 0) throw std::logic_error("ShellSection::advance_sensitivities without pseudo_resultants");
  const int q = linear_count_, slots = sens_trial_.slots();
  for (int l = 0; l < layers(); ++l) {
    // The strain's derivatives beyond the explicit part the Jets already carry (the lever arm's).
    const double z = rule_->zeta[static_cast<std::size_t>(l)] * 0.5 * h_;
    Eigen::Matrix<double, 3, material::kSensitivitySlots> de;
    for (int i = 0; i < 3; ++i) de.row(i) = material::derivatives_of(e(i)) + z * material::derivatives_of(kappa(i));
    // Only the parameters' slots 0 .. q - 1 are nonzero, before (with the strain's q .. q + 2) and
    // after; the strains' derivatives have none beyond them.
    for (int f = 0; f < LayerDerivatives::kFields; ++f) {
      const double* x = linear_.at(l, f);
      double* out = sens_trial_.at(l, f);
      for (int k = 0; k < q; ++k) {
        double v = x[k];
        for (int i = 0; i < 3; ++i) v += x[q + i] * de(i, k);
        out[k] = v;
      }
      for (int k = q; k < slots; ++k) out[k] = 0.0;
    }
  }
  e_sens_ = e;
  kappa_sens_ = kappa;
  sens_trial_set_ = true;
  linear_count_ = -1;
}

SectionStatus ShellSection::integrate_sensitivities(const SensLaw& law, const Vec3S& e, const Vec3S& kappa, int strain_slot, Vec6S* resultant) {
  return integrate_layers(law, e, kappa, strain_slot, resultant);
}

template <typename J>
SectionStatus ShellSection::integrate_layers(const material::ReturnMapping<J, 3>& law, const Vec3S& e_full, const Vec3S& kappa_full, int strain_slot,
                                             Vec6S* resultant) {
  if (!sensitivities_enabled()) throw std::logic_error("ShellSection::update_sensitivities before enable_sensitivities");
  constexpr int N = J::DIMENSION;
  using VecJ = Eigen::Matrix<J, 3, 1>;
  const auto narrow = [](const Sens& x) { return material::narrowed<N>(x); };
  const auto widen = [](const J& x) { return material::widened<N>(x); };
  const auto with = [](double v, const Eigen::Matrix<double, 1, N>& d) {
    J out(v);
    out.v = d.transpose();
    return out;
  };
  // The trial derivatives, or with the strain's slots the linearisation.
  LayerDerivatives& out = strain_slot >= 0 ? linear_ : sens_trial_;
  SectionStatus status;
  Eigen::Matrix<J, 6, 1> sum = Eigen::Matrix<J, 6, 1>::Zero();
  VecJ e, kappa;
  for (int i = 0; i < 3; ++i) {
    e(i) = narrow(e_full(i));
    kappa(i) = narrow(kappa_full(i));
  }
  const J h = narrow(material::with_derivatives(h_, dh_));
  for (std::size_t l = 0; l < points_.size(); ++l) {
    const J z = (rule_->zeta[l] * 0.5) * h;
    const double w = rule_->weight[l] * 0.5 * h0_;
    VecJ green = e + z * kappa;
    if (strain_slot >= 0)
      for (int i = 0; i < 3; ++i) green(i).v(strain_slot + i) += 1.0;
    // eps and d eps / d E with their derivatives by the chain rule through the closed-form first
    // and second derivatives of the logarithm.
    Vec3 gv;
    Eigen::Matrix<double, 3, N> gd;
    for (int i = 0; i < 3; ++i) {
      gv(i) = green(i).a;
      gd.row(i) = green(i).v.transpose();
    }
    const LogStrain ls = log_strain_with_derivatives(gv, true);
    VecJ eps;
    Eigen::Matrix<J, 3, 3> first;  // d eps_i / d E_j
    for (int i = 0; i < 3; ++i) {
      eps(i) = with(ls.value(i), ls.first.row(i) * gd);
      for (int j = 0; j < 3; ++j) first(i, j) = with(ls.first(i, j), ls.second[static_cast<std::size_t>(i)].row(j) * gd);
    }
    VecJ eps0;
    const int li = static_cast<int>(l);
    for (int i = 0; i < 3; ++i) eps0(i) = sens_.seeded<J>(li, 4 * i + 3, eps_[l](i));
    const material::MaterialState<J, 3> s0 = sens_.seeded_state<J>(li, points_[l].committed());
    material::MaterialState<J, 3> s1;
    const material::UpdateResult r = law.integrate(s0, VecJ(eps - eps0), s1, nullptr);
    if (!r.ok()) {
      status.ok = false;
      status.layer = static_cast<int>(l);
      status.reason = std::string("sensitivities: ") + r.reason;
      status.suggested_scale = r.suggested_scale;
      resultant->setZero();
      return status;
    }
    const VecJ stress = first.transpose() * s1.stress;
    sum.template head<3>() += w * stress;
    sum.template tail<3>() += (w * z) * stress;
    out.store(li, s1, eps);
  }
  for (int i = 0; i < 6; ++i) (*resultant)(i) = widen(sum(i));
  return status;
}

// The committed derivatives: the layers' trial ones, and the thickness's and the layers'
// reference log strains with the new lever arm.
void ShellSection::commit_sensitivities() {
  if (!sens_trial_set_) throw std::logic_error("a section with sensitivities committed without update_sensitivities");
  sens_.swap(sens_trial_);  // the next increment's passes write every layer's trial derivatives anew
  // On the narrowest Jets that hold the strains' derivatives (those of the parameters).
  int used = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < material::kSensitivitySlots; ++k)
      if (e_sens_(i).v(k) != 0.0 || kappa_sens_(i).v(k) != 0.0) used = std::max(used, k + 1);
  if (used <= 4)
    commit_thickness<material::FourSlotScalar>();
  else if (used <= 6)
    commit_thickness<material::SixSlotScalar>();
  else
    commit_thickness<Sens>();
  sens_trial_set_ = false;
}

// The thickness at constant volume and the layers' reference log strains with its new lever
// arm, as commit() computes their values, here with their derivatives on the Jets J.
template <typename J>
void ShellSection::commit_thickness() {
  using std::sqrt;
  constexpr int N = J::DIMENSION;
  Eigen::Matrix<J, 3, 1> e, kappa;
  for (int i = 0; i < 3; ++i) {
    e(i) = material::narrowed<N>(e_sens_(i));
    kappa(i) = material::narrowed<N>(kappa_sens_(i));
  }
  const J c11 = 1.0 + 2.0 * e(0), c22 = 1.0 + 2.0 * e(1);
  const J det = c11 * c22 - e(2) * e(2);
  if (value_of(det) > 0.0) {
    const J h = h0_ / sqrt(det);
    dh_ = material::derivatives_of(material::widened<N>(h));
    for (std::size_t l = 0; l < points_.size(); ++l) {
      const Eigen::Matrix<J, 3, 1> eps = log_strain_of_green(Eigen::Matrix<J, 3, 1>(e + ((rule_->zeta[l] * 0.5) * h) * kappa));
      for (int i = 0; i < 3; ++i) sens_.store(static_cast<int>(l), 4 * i + 3, eps(i));
    }
  }
}

SectionEnergy ShellSection::energy() const {
  SectionEnergy out;
  for (std::size_t l = 0; l < points_.size(); ++l) {
    const double w = rule_->weight[l] * 0.5 * h0_;
    const auto& st = points_[l].committed();
    out.elastic += w * 0.5 * st.stress.dot(compliance_ * st.stress);
    out.plastic += w * st.plastic_work;
  }
  return out;
}

void ShellSection::commit() {
  for (std::size_t l = 0; l < points_.size(); ++l) {
    points_[l].commit();
    eps_[l] = eps_trial_[l];
    tangent_[l] = tangent_trial_[l];
  }
  e_committed_ = e_trial_;
  if (sensitivities_enabled()) commit_sensitivities();
  const double c11 = 1.0 + 2.0 * e_trial_(0), c22 = 1.0 + 2.0 * e_trial_(1);
  const double det = c11 * c22 - e_trial_(2) * e_trial_(2);
  const double h_new = det > 0.0 ? h0_ / std::sqrt(det) : h_;  // update() refused det <= 0
  if (h_new != h_) {
    h_ = h_new;
    for (std::size_t l = 0; l < points_.size(); ++l)
      eps_[l] = eps_trial_[l] = log_strain_value(e_trial_ + rule_->zeta[l] * 0.5 * h_ * kappa_trial_);
  }
}

void ShellSection::revert() {
  for (std::size_t l = 0; l < points_.size(); ++l) {
    points_[l].revert();
    eps_trial_[l] = eps_[l];
    tangent_trial_[l] = tangent_[l];
  }
  e_trial_ = e_committed_;
  if (sensitivities_enabled()) {  // the trial derivatives are written anew before a commit uses them
    sens_trial_set_ = false;
    linear_count_ = -1;
  }
}

void ShellSection::save_state(io::BinaryWriter& w) const {
  w.f64(h_);
  w.vec3(e_committed_);
  w.i64(static_cast<std::int64_t>(points_.size()));
  for (std::size_t l = 0; l < points_.size(); ++l) {
    const auto& s = points_[l].committed();
    w.vec3(s.stress);
    w.vec3(s.plastic_strain);
    w.vec3(s.back_stress);
    w.f64(s.back_stress_zz);
    w.f64(s.eqps);
    w.f64(s.plastic_work);
    w.vec3(eps_[l]);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) w.f64(tangent_[l](i, j));
  }
}

void ShellSection::load_state(io::BinaryReader& r) {
  h_ = r.f64();
  e_committed_ = e_trial_ = r.vec3();
  r.expect_count("layers", static_cast<std::int64_t>(points_.size()));
  for (std::size_t l = 0; l < points_.size(); ++l) {
    material::MaterialState<double, 3> s;
    s.stress = r.vec3();
    s.plastic_strain = r.vec3();
    s.back_stress = r.vec3();
    s.back_stress_zz = r.f64();
    s.eqps = r.f64();
    s.plastic_work = r.f64();
    points_[l].set_committed(s);
    eps_[l] = eps_trial_[l] = r.vec3();
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) tangent_[l](i, j) = r.f64();
    tangent_trial_[l] = tangent_[l];
  }
}

namespace {

void write_slots(io::BinaryWriter& w, const double* d, int count) {
  for (int k = 0; k < count; ++k) w.f64(d[k]);
}

}  // namespace

// Every field the next increment reads, in the table's order (layer_derivatives.hpp).
void ShellSection::save_sensitivities(io::BinaryWriter& w, int count) const {
  if (!sensitivities_enabled()) throw std::logic_error("ShellSection::save_sensitivities before enable_sensitivities");
  if (count > sens_.slots()) throw std::logic_error("ShellSection::save_sensitivities: more parameters than slots enabled");
  write_slots(w, dh_.data(), count);
  w.i64(static_cast<std::int64_t>(sens_.layers()));
  for (int l = 0; l < sens_.layers(); ++l)
    for (int f = 0; f < LayerDerivatives::kFields; ++f) write_slots(w, sens_.at(l, f), count);
}

void ShellSection::load_sensitivities(io::BinaryReader& r, int count) {
  if (!sensitivities_enabled()) throw std::logic_error("ShellSection::load_sensitivities before enable_sensitivities");
  if (count > sens_.slots()) throw std::logic_error("ShellSection::load_sensitivities: more parameters than slots enabled");
  dh_.setZero();
  for (int k = 0; k < count; ++k) dh_(k) = r.f64();
  r.expect_count("layers with sensitivities", static_cast<std::int64_t>(sens_.layers()));
  for (int l = 0; l < sens_.layers(); ++l)
    for (int f = 0; f < LayerDerivatives::kFields; ++f) {
      double* d = sens_.at(l, f);
      for (int k = 0; k < sens_.slots(); ++k) d[k] = k < count ? r.f64() : 0.0;
    }
  sens_trial_ = sens_;
  sens_trial_set_ = false;
  linear_count_ = -1;
}

}  // namespace spifit::element
