#pragma once
// What tells a live run from a dead one (docs/reference/file-formats.md, "Run status"). While a run goes
// on, DIR/summary.json says "status": "running" with the process that runs it ("pid", "host"),
// when it started ("started") and a "heartbeat" (UTC times, ISO 8601), rewritten atomically at
// most every "heartbeat_interval" seconds as the run makes progress (FE increments; a fit's or
// sweep's clock). A killed run keeps its last heartbeat and its pid is gone: `spifit status DIR`
// tells the two apart.
#include "forward/io/host_and_time.hpp"
#include "forward/scenes/common/run_files.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <ctime>
#include <mutex>
#include <string>

namespace spifit::scene {

// Seconds between two heartbeats of a running summary.
constexpr double kHeartbeatSeconds = 10.0;

using io::host_name;
using io::parse_utc_iso;
using io::utc_iso;

class RunHeartbeat {
 public:
  // running: the head of the running summary (the run's inputs); status "running", pid, host,
  // started, heartbeat and heartbeat_interval are added here. Nothing is written yet.
  RunHeartbeat(RunFiles files, nlohmann::json running, double interval_seconds = kHeartbeatSeconds);

  // Writes the running summary now (with its progress so far).
  void write();
  // Due when the interval has passed since the last write: one clock read.
  bool due() const { return std::chrono::steady_clock::now().time_since_epoch().count() - last_.load() >= interval_.count(); }
  // The running summary with this "progress", written when due.
  void beat(nlohmann::json progress);
  // Writes `final` as the summary unless stop() came first, then stops. Thread-safe (the
  // heartbeat of a fit beats on a thread of its own).
  bool finish(const nlohmann::json& final);
  // No more heartbeats: the caller writes the final summary.
  void stop();

  // The running summary as last written (a copy: thread-safe).
  nlohmann::json running() const;
  // The running summary without what only a live run has (pid, host, heartbeat,
  // heartbeat_interval): the head of a final summary (failed, interrupted).
  nlohmann::json ended() const;

 private:
  void write_locked();
  RunFiles files_;
  nlohmann::json running_;
  std::chrono::steady_clock::duration interval_;
  std::atomic<std::chrono::steady_clock::rep> last_;  // of the last write (read by due() without the lock)
  mutable std::mutex mutex_;
  bool stopped_ = false;
};

}  // namespace spifit::scene
