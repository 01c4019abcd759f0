#pragma once
// SIGINT and SIGTERM while a command runs (docs/reference/file-formats.md, "Run status"): a thread of its
// own receives them (start_signal_thread) and, while an InterruptHandlers lives, only records
// them; an FE run (`spifit run`) reads it after every increment
// (scene::RunControl::interrupt) and ends with a checkpoint and status "interrupted"; a fit or
// a sweep is ended by its watch (RunWatch) at once with status "interrupted". A second signal
// of the same kind ends the process as it would without spifit's handler.
#include "forward/scenes/common/run_heartbeat.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace spifit::cli {

// Blocks SIGINT and SIGTERM in the calling thread and every thread created after it, and starts
// the thread that receives them. Call first in main(), before any other thread exists.
void start_signal_thread();

// The signal received (SIGINT, SIGTERM), 0 before any.
const std::atomic<int>& interrupt_signal();
// The exit code of a run ended by signal sig: 128 + sig (130 for SIGINT, 143 for SIGTERM), as a
// shell reports a process killed by it.
inline int interrupted_exit_code(int sig) { return 128 + sig; }
// "SIGINT", "SIGTERM", "signal N".
std::string signal_name(int sig);

// While one lives, the first SIGINT and the first SIGTERM are recorded (interrupt_signal) instead
// of ending the process; a second one of the same kind ends it. A signal ignored when the process
// started (nohup, a background job of a script) stays ignored.
class InterruptHandlers {
 public:
  InterruptHandlers();
  ~InterruptHandlers();
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;
};

// The heartbeat of a fit or a sweep, on a thread of its own: every heartbeat interval the
// running summary is rewritten with progress(); on SIGINT or SIGTERM, interrupted(sig) gives the
// final summary (status "interrupted"), written unless the command has finished, and the process
// ends with interrupted_exit_code(sig). Installs the signal handlers; stop() (or the destructor)
// ends the thread before the command writes its own final summary.
class RunWatch {
 public:
  RunWatch(scene::RunHeartbeat& heartbeat, std::function<nlohmann::json()> progress, std::function<nlohmann::json(int sig)> interrupted);
  ~RunWatch();
  RunWatch(const RunWatch&) = delete;
  RunWatch& operator=(const RunWatch&) = delete;
  void stop();

 private:
  void loop();
  scene::RunHeartbeat& heartbeat_;
  std::function<nlohmann::json()> progress_;
  std::function<nlohmann::json(int)> interrupted_;
  InterruptHandlers handlers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace spifit::cli
