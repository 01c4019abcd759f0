#include "forward/solver/newton_state.hpp"

#include "forward/io/binary_archive.hpp"

#include <cmath>
#include <initializer_list>
#include <string>

namespace spifit::solver {

void save_newton_state(io::BinaryWriter& w, const NewtonState& s) {
  w.section("newton_state");
  w.f64(s.lambda);
  w.f64(s.increment);
  w.f64(s.ceiling);
  w.vector(s.last_increment);
  w.f64(s.last_increment_size);
  const NewtonCounters& c = s.counters;
  for (int n : {c.increments, c.iterations, c.cutbacks, c.cholmod_factorisations, c.umfpack_factorisations, c.symbolic_analyses})
    w.i64(n);
  for (double v : {c.element_seconds, c.scatter_seconds, c.linear_seconds}) w.f64(v);
  w.section("stabilisation");
  w.f64(s.damping);
  for (int n : {s.stabilised_left, c.stabilised_increments}) w.i64(n);
  for (double v : {c.viscous_work, c.max_viscous_force}) w.f64(v);
  w.section("assemblies");
  for (int n : {c.tangent_assemblies, c.residual_assemblies, c.tangent_reassemblies}) w.i64(n);
  if (s.sensitivities) {  // a plain run's state is as it was
    w.section("sensitivity_solves");
    const SensitivitySolveStats& t = s.sensitivity_solves;
    for (int n : {t.increments, t.gmres_solves, t.gmres_iterations, t.factorisations}) w.i64(n);
    w.f64(t.solve_seconds);
  }
}

namespace {
// Counters are ints stored as i64: a value outside [0, 2e9] is a damaged archive.
void read_counters(io::BinaryReader& r, std::initializer_list<int*> counters, const char* what) {
  for (int* n : counters) {
    const std::int64_t v = r.i64();
    if (v < 0 || v > 2'000'000'000) throw io::ArchiveError(std::string("invalid ") + what + " counter " + std::to_string(v));
    *n = static_cast<int>(v);
  }
}
}  // namespace

NewtonState load_newton_state(io::BinaryReader& r, bool sensitivities) {
  r.section("newton_state");
  NewtonState s;
  s.lambda = r.f64();
  s.increment = r.f64();
  s.ceiling = r.f64();
  s.last_increment = r.vector();
  s.last_increment_size = r.f64();
  NewtonCounters& c = s.counters;
  read_counters(r, {&c.increments, &c.iterations, &c.cutbacks, &c.cholmod_factorisations, &c.umfpack_factorisations, &c.symbolic_analyses},
                "Newton");
  c.element_seconds = r.f64();
  c.scatter_seconds = r.f64();
  c.linear_seconds = r.f64();
  r.section("stabilisation");
  s.damping = r.f64();
  read_counters(r, {&s.stabilised_left, &c.stabilised_increments}, "stabilisation");
  c.viscous_work = r.f64();
  c.max_viscous_force = r.f64();
  if (!(s.damping >= 0.0 && std::isfinite(s.damping) && c.viscous_work >= 0.0 && c.max_viscous_force >= 0.0))
    throw io::ArchiveError("invalid stabilisation state");
  r.section("assemblies");
  read_counters(r, {&c.tangent_assemblies, &c.residual_assemblies, &c.tangent_reassemblies}, "assembly");
  if (!(std::isfinite(s.lambda) && s.increment > 0.0 && s.ceiling > 0.0)) throw io::ArchiveError("invalid Newton stepping state");
  if (sensitivities) {
    r.section("sensitivity_solves");
    SensitivitySolveStats& t = s.sensitivity_solves;
    read_counters(r, {&t.increments, &t.gmres_solves, &t.gmres_iterations, &t.factorisations}, "sensitivity solve");
    t.solve_seconds = r.f64();
    s.sensitivities = true;
  }
  return s;
}

}  // namespace spifit::solver
