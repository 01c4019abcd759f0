#pragma once
// How a run ended (summary.json "status"): running until it ends; ok; failed (a numerical
// failure, with where and why in the message); stopped (by the caller: a test's stop option);
// timed_out (its RunControl time limit passed: a fit's limit on one forward run); interrupted (by
// SIGINT or SIGTERM: an FE run at the end of an increment, after a checkpoint; a fit or sweep at
// once). A "running" summary carries pid, host and heartbeat (run_heartbeat.hpp).
#include <string>

namespace spifit::scene {

enum class RunStatus { running, ok, failed, stopped, timed_out, interrupted };

inline const char* to_string(RunStatus s) {
  switch (s) {
    case RunStatus::ok: return "ok";
    case RunStatus::failed: return "failed";
    case RunStatus::stopped: return "stopped";
    case RunStatus::timed_out: return "timed_out";
    case RunStatus::interrupted: return "interrupted";
    case RunStatus::running: break;
  }
  return "running";
}

}  // namespace spifit::scene
