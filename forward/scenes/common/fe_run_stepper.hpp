#pragma once
// FeRun's bookkeeping between two increments (fe_run.cpp, fe_run_explicit.cpp): counts, marks,
// wall times, checkpoints, the periodic writes and the stop options. Internal to FeRun.
#include "forward/io/input_error.hpp"
#include "forward/scenes/common/failure_words.hpp"
#include "forward/scenes/common/fe_run.hpp"
#include "forward/scenes/common/run_checkpoint.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>

namespace spifit::scene {

using FeRunClock = std::chrono::steady_clock;

inline void report_progress(const ProgressSink& sink, ProgressEvent::Kind kind, std::string text, double fraction, double load) {
  if (sink) sink({kind, std::move(text), fraction, load});
}

// The bookkeeping of one run between two increments: counts, marks, wall times, checkpoints,
// the periodic writes and the stop options. The callback of the Newton solver.
class FeRun::Stepper {
 public:
  Stepper(FeRun& run, const RunInputs& inputs, FeRunClock::time_point t0, RunHeartbeat& heartbeat)
      : run_(run), inputs_(inputs), t0_(t0), heartbeat_(heartbeat) {}

  RunLog log;
  CheckpointRecord checkpoints;
  bool stopped = false, timed_out = false;
  int interrupted = 0;  // the signal that ended the run
  const DynamicsView* dynamics = nullptr;  // set by an explicit run before each call
  const CheckpointPart* explicit_part = nullptr;  // an explicit run's state for its checkpoints

  double wall() const { return std::chrono::duration<double>(FeRunClock::now() - t0_).count(); }
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
                          run_.control_.progress, dynamics};
    const double fraction = travel / s.load_map.length();
    notes(ir, travel, fraction);
    for (auto& o : run_.observers_) o->after_increment(v);
    const bool marked = reach_marks(v);
    const auto now = FeRunClock::now();
    const bool periodic = now - last_write_ >= std::chrono::seconds(1);
    if (periodic) last_write_ = now;
    const WriteReason reason = marked ? WriteReason::mark : periodic ? WriteReason::periodic : WriteReason::increment;
    for (auto& o : run_.observers_) o->write(reason);
    if (run_.control_.progress) {
      // Every increment reports its fraction of the path (a progress meter); the line of text
      // only where the scene asks for one per increment (the cone's come per contour).
      char buf[200] = "";
      if (s.progress_every_increment)
        std::snprintf(buf, sizeof buf, "%s %d: travel %.2f / %.2f mm, %d %s", dynamics ? "interval" : "increment", log.increments, travel,
                      s.load_map.length(), ir.iterations, dynamics ? "steps" : "iterations");
      report_progress(run_.control_.progress, ProgressEvent::Kind::increment, buf, fraction, ir.lambda);
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

  // The outcome of a run that ended (either scheme): status and message from how it ended, the
  // observers' end and their last write. resumed_at_mark: -1 for a fresh run.
  FeRunOutcome finish(bool converged, double lambda, const std::string& failure, int resumed_at_mark) {
    FeRunOutcome out;
    const FeRunSetup& s = run_.setup_;
    out.travel_reached = s.load_map.travel(lambda);
    out.marks_reached = log.marks_reached;
    out.mark_wall_seconds = log.mark_wall;
    out.resumed_at_mark = resumed_at_mark;
    out.checkpoints = checkpoints;
    if (interrupted) {
      // As a stop: the files hold every increment so far, the checkpoint the state after the last.
      out.status = RunStatus::interrupted;
      out.message = std::string("interrupted by ") + (interrupted == SIGINT ? "SIGINT" : interrupted == SIGTERM ? "SIGTERM" : "a signal") +
                    " at tool travel " + std::to_string(out.travel_reached) + " mm, after " + std::to_string(log.increments) +
                    " increments, " + std::to_string(log.marks_reached) + " marks" +
                    (checkpoints.written > 0 ? "; checkpoint/state.bin holds the state after the last one" : "");
    } else if (stopped) {
      // As a kill may leave it: the files hold every increment so far, no final VTU step.
      out.status = RunStatus::stopped;
      out.message = "stopped after " + std::to_string(log.increments) + " increments, " + std::to_string(log.marks_reached) +
                    " marks (test option)";
    } else {
      for (auto& o : run_.observers_) o->at_end(*run_.model_, s.time_of_travel(out.travel_reached));
      out.status = timed_out ? RunStatus::timed_out : converged ? RunStatus::ok : RunStatus::failed;
      if (timed_out) {
        out.message = "time limit of " + io::format_number(run_.control_.time_limit_seconds) + " s passed at tool travel " +
                      std::to_string(out.travel_reached) + " mm, after " + std::to_string(log.increments) + " increments";
      } else if (!converged) {
        out.message = "at tool travel " + std::to_string(out.travel_reached) + " mm: " + failure_in_words(failure);
      }
    }
    for (auto& o : run_.observers_) o->write(WriteReason::end);
    out.wall_seconds = wall();
    return out;
  }

 private:
  FeRun& run_;
  const RunInputs& inputs_;
  FeRunClock::time_point t0_;
  RunHeartbeat& heartbeat_;
  FeRunClock::time_point last_write_ = FeRunClock::now();
  int last_checkpoint_marks_ = 0, last_checkpoint_increments_ = 0;

  // Increments accepted by a rule other than the plain convergence test are worth a line.
  void notes(const solver::IncrementReport& ir, double travel, double fraction) const {
    char buf[240];
    if (ir.force_only) {
      std::snprintf(buf, sizeof buf, "increment %d at travel %.6f mm accepted on the force test alone at the minimum increment (relative residual %.3g)",
                    ir.index, travel, ir.residual_norms.empty() ? 0.0 : ir.residual_norms.back());
      report_progress(run_.control_.progress, ProgressEvent::Kind::note, buf, fraction, ir.lambda);
    }
    if (ir.damping > 0.0) {
      std::snprintf(buf, sizeof buf,
                    "increment %d at travel %.6f mm stabilised (damping factor %.3g): viscous work %.3g N mm, viscous force %.3g of the force scale",
                    ir.index, travel, ir.damping, ir.viscous_work, ir.viscous_force);
      report_progress(run_.control_.progress, ProgressEvent::Kind::note, buf, fraction, ir.lambda);
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
    // is where the run goes on; an explicit run is called at an output point, after its force
    // filter was reset.
    const auto c0 = FeRunClock::now();
    log.wall_seconds = std::chrono::duration<double>(c0 - t0_).count();
    const solver::NewtonState& newton = run_.solver_->state();  // an explicit run's is not saved
    checkpoints.bytes = write_run_checkpoint(*run_.files_.directory(), inputs_, *run_.model_, explicit_part ? nullptr : &newton,
                                             explicit_part, log, run_.observers_);
    const double dt = std::chrono::duration<double>(FeRunClock::now() - c0).count();
    checkpoints.write_seconds += dt;
    ++checkpoints.written;
    last_checkpoint_marks_ = log.marks_reached;
    last_checkpoint_increments_ = log.increments;
    char buf[160];
    std::snprintf(buf, sizeof buf, "checkpoint after %d increments, %d marks: %zu bytes in %.3f s", log.increments, log.marks_reached,
                  checkpoints.bytes, dt);
    const double load = run_.model_->load_factor();
    report_progress(run_.control_.progress, ProgressEvent::Kind::checkpoint, buf, run_.setup_.load_map.travel(load) / run_.setup_.load_map.length(), load);
  }
};

}  // namespace spifit::scene
