#include "cli/run_signals.hpp"

#include "forward/io/directory_lock.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <thread>
#include <pthread.h>
#include <unistd.h>

namespace spifit::cli {
namespace {

static_assert(std::atomic<int>::is_always_lock_free, "the signal thread stores into a lock-free atomic");
std::atomic<int> g_signal{0};
std::atomic<int> g_armed{0};  // InterruptHandlers alive
sigset_t g_handled;           // SIGINT and SIGTERM, unless the process started with them ignored

// The signal thread: every other thread blocks SIGINT and SIGTERM (start_signal_thread, before
// any other thread exists), so they arrive here, synchronously, and never interrupt the
// computing threads (an asynchronous handler crashed a fit under load: a corrupted stack in the
// main thread while an OpenMP loop ran). Armed, the first of each kind is recorded; otherwise,
// or the second time, the default action ends the process.
void signal_loop() {
  for (;;) {
    int sig = 0;
    if (sigwait(&g_handled, &sig) != 0) continue;
    if (g_armed.load() > 0 && g_signal.load() != sig) {
      g_signal.store(sig);
      continue;
    }
    std::signal(sig, SIG_DFL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, sig);
    pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
    std::raise(sig);  // to this thread, the only one that does not block it: the default action
  }
}

}  // namespace

void start_signal_thread() {
  sigemptyset(&g_handled);
  for (int sig : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    sigaction(sig, nullptr, &old);
    // A signal the process was started to ignore (`nohup`, a shell's background job) stays ignored.
    if (old.sa_handler != SIG_IGN) sigaddset(&g_handled, sig);
  }
  pthread_sigmask(SIG_BLOCK, &g_handled, nullptr);  // inherited by every thread created from now on
  std::thread(signal_loop).detach();
}

const std::atomic<int>& interrupt_signal() { return g_signal; }

std::string signal_name(int sig) {
  if (sig == SIGINT) return "SIGINT";
  if (sig == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(sig);
}

InterruptHandlers::InterruptHandlers() { ++g_armed; }

InterruptHandlers::~InterruptHandlers() { --g_armed; }

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
      // The command has not finished (stop() would have come first): its final summary is this,
      // and its message (how to go on) goes to stderr too.
      const nlohmann::json summary = interrupted_(sig);
      if (heartbeat_.finish(summary)) {
        std::fflush(stdout);
        const auto m = summary.find("message");
        std::cerr << "spifit: " << (m != summary.end() && m->is_string() ? m->get<std::string>() : "interrupted by " + signal_name(sig)) << "\n";
        io::DirectoryLock::release_all();  // _Exit runs no destructor: no stale lock for the resume
        std::_Exit(interrupted_exit_code(sig));
      }
      return;
    }
    if (heartbeat_.due()) heartbeat_.beat(progress_());
  }
}

}  // namespace spifit::cli
