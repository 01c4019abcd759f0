#include "forward/solver/stabilisation.hpp"

#include <algorithm>

namespace spifit::solver {

ViscousForces::ViscousForces(double damping, const SparseMatrix& k, Eigen::Index n) : damping_(damping) {
  if (!active()) return;
  viscosity_ = damping * k.diagonal().cwiseAbs();
  du_bar_ = Eigen::VectorXd::Zero(n);
}

void ViscousForces::add_to_tangent(SparseMatrix* k) const {
  if (active()) k->add_to_diagonal(viscosity_);
}

void ViscousForces::add_to_residual(Eigen::VectorXd* r, const Eigen::VectorXd& du, double alpha) const {
  if (active()) *r += viscosity_.cwiseProduct(du_bar_ + alpha * du);
}

void ViscousForces::accept(const Eigen::VectorXd& du, double alpha) {
  if (active()) du_bar_ += alpha * du;
}

void ViscousForces::report(double force_scale, IncrementReport* report) const {
  if (!active()) return;
  const Eigen::VectorXd v = viscosity_.cwiseProduct(du_bar_);
  report->damping = damping_;
  report->viscous_work = du_bar_.dot(v);
  report->viscous_force = v.norm() / force_scale;
}

Stabilisation::Stabilisation(const NewtonOptions& options)
    : options_(options), max_damping_(options.max_stabilisation > 0.0 ? options.max_stabilisation : 100.0 * options.stabilisation) {}

void Stabilisation::restore(double damping, int increments_left) {
  damping_ = damping;
  left_ = increments_left;
}

void Stabilisation::converged(const IncrementReport& report, NewtonCounters* counters) {
  if (!(report.damping > 0.0)) return;
  ++counters->stabilised_increments;
  counters->viscous_work += report.viscous_work;
  counters->max_viscous_force = std::max(counters->max_viscous_force, report.viscous_force);
  if (--left_ <= 0) damping_ = 0.0;
}

bool Stabilisation::escalate() {
  if (!(options_.stabilisation > 0.0 && damping_ < max_damping_ * (1.0 - 1e-12))) return false;
  damping_ = damping_ > 0.0 ? std::min(max_damping_, 10.0 * damping_) : options_.stabilisation;
  left_ = options_.stabilised_increments;
  return true;
}

}  // namespace spifit::solver
