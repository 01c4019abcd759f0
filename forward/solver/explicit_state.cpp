#include "forward/solver/explicit_state.hpp"

#include "forward/io/binary_archive.hpp"

namespace spifit::solver {

void save_explicit_state(io::BinaryWriter& w, const ExplicitState& s) {
  w.section("explicit_state");
  w.boolean(s.started);
  w.vector(s.v);
  w.vector(s.a);
  w.vector(s.damping_force);
  for (double x : {s.damping_work, s.lambda, s.time}) w.f64(x);
  w.i64(s.steps);
  w.i64(s.cut_steps);
  for (double x : {s.min_step, s.max_step, s.step_bound}) w.f64(x);
  w.i64(s.outputs);
}

ExplicitState load_explicit_state(io::BinaryReader& r) {
  r.section("explicit_state");
  ExplicitState s;
  s.started = r.boolean();
  s.v = r.vector();
  s.a = r.vector();
  s.damping_force = r.vector();
  s.damping_work = r.f64();
  s.lambda = r.f64();
  s.time = r.f64();
  s.steps = r.i64();
  s.cut_steps = r.i64();
  s.min_step = r.f64();
  s.max_step = r.f64();
  s.step_bound = r.f64();
  const std::int64_t outputs = r.i64();
  if (s.v.size() != s.a.size() || (s.damping_force.size() != 0 && s.damping_force.size() != s.v.size()))
    throw io::ArchiveError("explicit state: velocity, acceleration and damping force of different sizes");
  if (s.steps < 0 || s.cut_steps < 0 || outputs < 0 || outputs > 2'000'000'000)
    throw io::ArchiveError("explicit state: invalid step or output point count");
  s.outputs = static_cast<int>(outputs);
  return s;
}

}  // namespace spifit::solver
