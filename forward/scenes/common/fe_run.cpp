#include "forward/scenes/common/fe_run.hpp"

#include "forward/io/input_error.hpp"
#include "forward/scenes/common/run_checkpoint.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>

namespace spifit::scene {
namespace {

using Clock = std::chrono::steady_clock;

void report(const ProgressSink& sink, ProgressEvent::Kind kind, std::string text, double fraction) {
  if (sink) sink({kind, std::move(text), fraction});
}

}  // namespace

// The bookkeeping of one run between two increments: counts, marks, wall times, checkpoints,
// the periodic writes and the stop options. The callback of the Newton solver.
class FeRun::Stepper {
 public:
  Stepper(FeRun& run, const RunInputs& inputs, Clock::time_point t0, RunHeartbeat& heartbeat)
      : run_(run), inputs_(inputs), t0_(t0), heartbeat_(heartbeat) {}

  RunLog log;
  CheckpointRecord checkpoints;
  bool stopped = false, timed_out = false;
  int interrupted = 0;  // the signal that ended the run

  double wall() const { return std::chrono::duration<double>(Clock::now() - t0_).count(); }
  void start_from(const RunLog& restored) {
    log = restored;
    last_checkpoint_marks_ = log.marks_reached;
    last_checkpoint_increments_ = log.increments;
  }

  bool operator()(const solver::IncrementReport& ir) {
    const FeRunSetup& s = run_.setup_;
    ++log.increments;
    const double travel = s.load_map.travel(ir.lambda);
    const IncrementView v{ir, log.increments, ir.lambda, travel, s.time_of_travel(travel), wall(), *run_.model_, *run_.tool_,
                          run_.control_.progress};
    const double fraction = travel / s.load_map.length();
    notes(ir, travel, fraction);
    for (auto& o : run_.observers_) o->after_increment(v);
    const bool marked = reach_marks(v);
    const auto now = Clock::now();
    const bool periodic = now - last_write_ >= std::chrono::seconds(1);
    if (periodic) last_write_ = now;
    const WriteReason reason = marked ? WriteReason::mark : periodic ? WriteReason::periodic : WriteReason::increment;
    for (auto& o : run_.observers_) o->write(reason);
    if (run_.control_.progress) {
      // Every increment reports its fraction of the path (a progress meter); the line of text
      // only where the scene asks for one per increment (the cone's come per contour).
      char buf[200] = "";
      if (s.progress_every_increment)
        std::snprintf(buf, sizeof buf, "increment %d: travel %.2f / %.2f mm, %d iterations", log.increments, travel, s.load_map.length(),
                      ir.iterations);
      report(run_.control_.progress, ProgressEvent::Kind::increment, buf, fraction);
    }
    const RunControl& c = run_.control_;
    const bool at_end = run_.model_->load_factor() >= 1.0 - 1e-12;
    const int sig = c.interrupt && !at_end ? c.interrupt->load() : 0;
    checkpoint_if_due(sig != 0);
    if (heartbeat_.due())
      heartbeat_.beat({{"increments", log.increments},
                       {"marks_reached", log.marks_reached},
                       {"marks", s.marks.size()},
                       {"travel_reached", travel},
                       {"travel", s.load_map.length()},
                       {"wall_seconds", v.wall_seconds}});
    if (sig != 0) {
      interrupted = sig;
      return false;
    }
    if ((c.stop_after_marks > 0 && log.marks_reached >= c.stop_after_marks) ||
        (c.stop_after_increments > 0 && log.increments >= c.stop_after_increments)) {
      stopped = true;
      return false;
    }
    if (c.time_limit_seconds > 0.0 && wall() > c.time_limit_seconds) {
      timed_out = true;
      return false;
    }
    return true;
  }

 private:
  FeRun& run_;
  const RunInputs& inputs_;
  Clock::time_point t0_;
  RunHeartbeat& heartbeat_;
  Clock::time_point last_write_ = Clock::now();
  int last_checkpoint_marks_ = 0, last_checkpoint_increments_ = 0;

  // Increments accepted by a rule other than the plain convergence test are worth a line.
  void notes(const solver::IncrementReport& ir, double travel, double fraction) const {
    char buf[240];
    if (ir.force_only) {
      std::snprintf(buf, sizeof buf, "increment %d at travel %.6f mm accepted on the force test alone at the minimum increment (relative residual %.3g)",
                    ir.index, travel, ir.residual_norms.empty() ? 0.0 : ir.residual_norms.back());
      report(run_.control_.progress, ProgressEvent::Kind::note, buf, fraction);
    }
    if (ir.damping > 0.0) {
      std::snprintf(buf, sizeof buf,
                    "increment %d at travel %.6f mm stabilised (damping factor %.3g): viscous work %.3g N mm, viscous force %.3g of the force scale",
                    ir.index, travel, ir.damping, ir.viscous_work, ir.viscous_force);
      report(run_.control_.progress, ProgressEvent::Kind::note, buf, fraction);
    }
  }

  // Marks whose travel the tool has reached, to within 1e-9 mm (marks at solver stops are hit
  // exactly; a cone's contour ends lie inside increments).
  bool reach_marks(const IncrementView& v) {
    const auto& marks = run_.setup_.marks;
    constexpr double tol = 1e-9;
    bool any = false;
    while (log.marks_reached < static_cast<int>(marks.size()) && marks[static_cast<std::size_t>(log.marks_reached)].travel <= v.travel + tol) {
      log.mark_wall.push_back(v.wall_seconds);
      const Mark& m = marks[static_cast<std::size_t>(log.marks_reached)];
      ++log.marks_reached;
      for (auto& o : run_.observers_) o->at_mark(m, v);
      any = true;
    }
    return any;
  }

  // now: an interrupted run's last checkpoint, due or not.
  void checkpoint_if_due(bool now) {
    const FeOutputOptions& o = run_.setup_.output;
    if (!run_.files_.enabled()) return;
    const bool by_marks = o.checkpoint_every > 0 && log.marks_reached >= last_checkpoint_marks_ + o.checkpoint_every;
    const bool by_count = o.checkpoint_increments > 0 && log.increments >= last_checkpoint_increments_ + o.checkpoint_increments;
    if (!now && !by_marks && !by_count) return;
    if (run_.model_->load_factor() >= 1.0 - 1e-12) return;  // the end of the path: nothing left to resume
    // The solver has chosen its next increment already (NewtonSolver's callback), so its state
    // is where the run goes on.
    const auto c0 = Clock::now();
    log.wall_seconds = std::chrono::duration<double>(c0 - t0_).count();
    checkpoints.bytes = write_run_checkpoint(*run_.files_.directory(), inputs_, *run_.model_, run_.solver_->state(), log, run_.observers_);
    const double dt = std::chrono::duration<double>(Clock::now() - c0).count();
    checkpoints.write_seconds += dt;
    ++checkpoints.written;
    last_checkpoint_marks_ = log.marks_reached;
    last_checkpoint_increments_ = log.increments;
    char buf[160];
    std::snprintf(buf, sizeof buf, "checkpoint after %d increments, %d marks: %zu bytes in %.3f s", log.increments, log.marks_reached,
                  checkpoints.bytes, dt);
    report(run_.control_.progress, ProgressEvent::Kind::checkpoint, buf, run_.setup_.load_map.travel(run_.model_->load_factor()) / run_.setup_.load_map.length());
  }
};

FeRun::FeRun(FeRunSetup setup, RunFiles files, RunControl control)
    : setup_(std::move(setup)), files_(files), control_(std::move(control)) {
  model_ = std::make_unique<model::ShellModel>(setup_.mesh, setup_.thickness, setup_.material, setup_.model);
  const toolpath::ToolPath& path = setup_.tool_path;
  const LoadMap& map = setup_.load_map;
  tool_ = &model_->add_contribution(std::make_unique<model::ToolContact>(
      setup_.mesh, setup_.tool_radius, [&path, &map](double lambda) { return path.at_distance(map.travel(lambda)); }, setup_.contact,
      setup_.spin_per_load_factor));
  if (!setup_.tool_copies_deg.empty()) tool_->set_copies(setup_.tool_copies_deg);
  constraints_ = std::make_unique<solver::DofConstraints>(setup_.constraints(*model_));
  solver_ = std::make_unique<solver::NewtonSolver>(*model_, *constraints_, setup_.newton);
}

FeRun::~FeRun() = default;

FeRunOutcome FeRun::run(const nlohmann::json& head) {
  auto t0 = Clock::now();
  // The input files' contents go into checkpoints (and are compared on resume): read only when
  // the run writes files; a sweep or fit point runs from the parsed scene alone.
  const RunInputs inputs = files_.enabled() ? read_run_inputs(setup_.kind, setup_.input_files) : RunInputs{};
  RunLog restored;
  if (control_.resume) {
    // The checkpoint is read (and refused with an InputError) before any output is touched.
    if (!files_.enabled()) throw std::logic_error("FeRun: a resume needs an output directory");
    solver::NewtonState newton;
    read_run_checkpoint(*files_.directory(), inputs, model_.get(), &newton, &restored, observers_);
    solver_->set_state(newton);
    t0 -= std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(restored.wall_seconds));
  }
  RunHeartbeat heartbeat(files_, head, control_.heartbeat_seconds);
  heartbeat.write();
  Stepper step(*this, inputs, t0, heartbeat);
  step.start_from(restored);
  step.checkpoints.every_marks = setup_.output.checkpoint_every;
  step.checkpoints.every_increments = setup_.output.checkpoint_increments;
  if (control_.resume)
    for (auto& o : observers_) o->write(WriteReason::end);  // the rows a killed run wrote after its checkpoint are dropped
  else
    for (auto& o : observers_) o->at_start(*model_);

  auto callback = [&step](const solver::IncrementReport& ir) { return step(ir); };
  const solver::NewtonSummary r = control_.resume ? solver_->resume(1.0, callback) : solver_->solve(0.0, 1.0, callback);

  FeRunOutcome out;
  out.counters = r.counters;
  out.travel_reached = setup_.load_map.travel(r.lambda);
  out.marks_reached = step.log.marks_reached;
  out.mark_wall_seconds = step.log.mark_wall;
  out.resumed_at_mark = control_.resume ? restored.marks_reached : -1;
  out.checkpoints = step.checkpoints;
  if (step.interrupted) {
    // As a stop: the files hold every increment so far, the checkpoint the state after the last.
    out.status = RunStatus::interrupted;
    out.message = std::string("interrupted by ") + (step.interrupted == SIGINT ? "SIGINT" : step.interrupted == SIGTERM ? "SIGTERM" : "a signal") +
                  " at tool travel " + std::to_string(out.travel_reached) + " mm, after " + std::to_string(step.log.increments) +
                  " increments, " + std::to_string(step.log.marks_reached) + " marks" +
                  (step.checkpoints.written > 0 ? "; checkpoint/state.bin holds the state after the last one" : "");
  } else if (step.stopped) {
    // As a kill may leave it: the files hold every increment so far, no final VTU step.
    out.status = RunStatus::stopped;
    out.message = "stopped after " + std::to_string(step.log.increments) + " increments, " + std::to_string(step.log.marks_reached) +
                  " marks (test option)";
  } else {
    for (auto& o : observers_) o->at_end(*model_, setup_.time_of_travel(out.travel_reached));
    out.status = step.timed_out ? RunStatus::timed_out : r.converged ? RunStatus::ok : RunStatus::failed;
    if (step.timed_out) {
      out.message = "time limit of " + io::format_number(control_.time_limit_seconds) + " s passed at tool travel " +
                    std::to_string(out.travel_reached) + " mm, after " + std::to_string(step.log.increments) + " increments";
    } else if (!r.converged) {
      out.message = "at tool travel " + std::to_string(out.travel_reached) + " mm: " + r.message;
    }
  }
  for (auto& o : observers_) o->write(WriteReason::end);
  out.wall_seconds = step.wall();
  return out;
}

}  // namespace spifit::scene
