#include "cli/run_signals.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <unistd.h>

namespace spifit::cli {
namespace {

static_assert(std::atomic<int>::is_always_lock_free, "the signal handler stores into a lock-free atomic");
std::atomic<int> g_signal{0};

void record_signal(int sig) { g_signal.store(sig); }

struct sigaction g_old_int, g_old_term;

}  // namespace

const std::atomic<int>& interrupt_signal() { return g_signal; }

std::string signal_name(int sig) {
  if (sig == SIGINT) return "SIGINT";
  if (sig == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(sig);
}

InterruptHandlers::InterruptHandlers() {
  struct sigaction sa {};
  sa.sa_handler = record_signal;
  sigemptyset(&sa.sa_mask);
  // SA_RESTART: writes and waits go on; SA_RESETHAND: a second signal acts as without handler.
  sa.sa_flags = SA_RESTART | SA_RESETHAND;
  sigaction(SIGINT, &sa, &g_old_int);
  sigaction(SIGTERM, &sa, &g_old_term);
  // A signal the process was started to ignore (`nohup`, a shell's background job) stays ignored.
  if (g_old_int.sa_handler == SIG_IGN) sigaction(SIGINT, &g_old_int, nullptr);
  if (g_old_term.sa_handler == SIG_IGN) sigaction(SIGTERM, &g_old_term, nullptr);
}

InterruptHandlers::~InterruptHandlers() {
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
}

RunWatch::RunWatch(scene::RunHeartbeat& heartbeat, std::function<nlohmann::json()> progress, std::function<nlohmann::json(int)> interrupted)
    : heartbeat_(heartbeat), progress_(std::move(progress)), interrupted_(std::move(interrupted)) {
  thread_ = std::thread([this] { loop(); });
}

RunWatch::~RunWatch() { stop(); }

void RunWatch::stop() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void RunWatch::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stop_; })) {
    if (const int sig = g_signal.load(); sig != 0) {
      // The command has not finished (stop() would have come first): its final summary is this.
      if (heartbeat_.finish(interrupted_(sig))) {
        std::fflush(stdout);
        std::cerr << "spifit: interrupted by " << signal_name(sig) << "\n";
        std::_Exit(interrupted_exit_code(sig));
      }
      return;
    }
    if (heartbeat_.due()) heartbeat_.beat(progress_());
  }
}

}  // namespace spifit::cli
