#include "cli/job_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace spifit::cli {

namespace {

std::string first_line(const std::filesystem::path& file) {
  std::ifstream f(file);
  std::string line;
  std::getline(f, line);
  return line;
}

struct Child {
  pid_t pid = -1;
  int out = -1;  // read end of its stdout
};

// Writes the job to the child's stdin. A child that is gone before it read it (killed, or ended)
// makes the write fail with EPIPE and raise SIGPIPE, whose default action would end this process,
// a worker rank of an MPI fit, with it: SIGPIPE is blocked in this thread for the write and a
// pending one taken back. The child's end is then reported by waitpid as for any other death.
void write_to_child(int fd, const std::string& input) {
  sigset_t pipe_signal, previous;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  ::pthread_sigmask(SIG_BLOCK, &pipe_signal, &previous);
  bool broken = false;
  std::size_t written = 0;
  while (written < input.size()) {
    const ssize_t n = ::write(fd, input.data() + written, input.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      broken = n < 0 && errno == EPIPE;
      break;
    }
    written += static_cast<std::size_t>(n);
  }
  if (broken && !sigismember(&previous, SIGPIPE)) {
    const timespec now{0, 0};
    while (::sigtimedwait(&pipe_signal, nullptr, &now) == SIGPIPE) {
    }
  }
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

// Starts this executable with args, input written to its stdin, stderr to err_name.
Child start_child(const std::vector<std::string>& args, const std::string& input, const std::string& err_name) {
  // Everything the child needs is prepared before fork: it only calls async-signal-safe functions.
  std::vector<std::string> words{"spifit"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  int to_child[2], from_child[2];
  if (::pipe(to_child) != 0) return {};
  if (::pipe(from_child) != 0) {
    ::close(to_child[0]);
    ::close(to_child[1]);
    return {};
  }
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(125);  // the parent died before prctl
    sigset_t none;  // the default signal mask (spifit blocks SIGINT and SIGTERM in its threads)
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    const int e = ::open(err_name.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    ::dup2(to_child[0], 0);
    ::dup2(from_child[1], 1);
    if (e >= 0) ::dup2(e, 2);
    ::close(to_child[1]);
    ::close(from_child[0]);
    ::execv("/proc/self/exe", argv.data());
    ::_exit(127);
  }
  ::close(to_child[0]);
  ::close(from_child[1]);
  if (pid < 0) {
    ::close(to_child[1]);
    ::close(from_child[0]);
    return {};
  }
  write_to_child(to_child[1], input);
  ::close(to_child[1]);
  return {pid, from_child[0]};
}

}  // namespace

ChildOutcome run_child(const std::vector<std::string>& args, const std::string& input, double kill_after_seconds) {
  static std::atomic<long> count{0};
  const std::filesystem::path err =
      std::filesystem::temp_directory_path() / ("spifit_job_" + std::to_string(::getpid()) + "_" + std::to_string(count++) + ".err");
  const Child child = start_child(args, input, err.string());
  if (child.pid < 0) return {false, "", "cannot start a process for the run"};
  ChildOutcome out;
  const auto t0 = std::chrono::steady_clock::now();
  bool killed = false;
  char buf[65536];
  for (;;) {
    pollfd p{child.out, POLLIN, 0};
    if (::poll(&p, 1, 100) > 0) {
      const ssize_t n = ::read(child.out, buf, sizeof buf);
      if (n > 0) {
        out.output.append(buf, static_cast<std::size_t>(n));
        continue;
      }
      if (n == 0) break;  // EOF: the child closed its stdout (ended)
    }
    if (kill_after_seconds > 0 && !killed &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > kill_after_seconds) {
      ::kill(child.pid, SIGKILL);
      killed = true;
    }
  }
  ::close(child.out);
  int status = 0;
  ::waitpid(child.pid, &status, 0);
  const std::string said = first_line(err);
  std::error_code ec;
  std::filesystem::remove(err, ec);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    out.ok = true;
    return out;
  }
  if (killed) out.why = "stopped after " + std::to_string(static_cast<long>(kill_after_seconds)) + " s";
  else if (WIFSIGNALED(status)) out.why = "killed by signal " + std::to_string(WTERMSIG(status));
  else out.why = "exit status " + std::to_string(WEXITSTATUS(status));
  if (!said.empty()) out.why += ": " + said;
  return out;
}

inverse::JobHandler jobs_in_child_processes(std::vector<std::string> args, double kill_after_seconds,
                                            std::function<std::string(const std::string&, const std::string&)> failed,
                                            std::function<void(const std::string&)> note) {
  return [args = std::move(args), kill_after_seconds, failed = std::move(failed), note = std::move(note)](const std::string& job) {
    std::string why;
    for (int attempt = 0; attempt < 2; ++attempt) {
      const ChildOutcome c = run_child(args, job, kill_after_seconds);
      if (c.ok) return c.output;
      why += (why.empty() ? "" : "; again: ") + c.why;
      if (note) note("the process of a forward run ended (" + c.why + ")" + (attempt == 0 ? ": running it once more" : ": a failed run"));
    }
    return failed(job, "the process of the run ended twice: " + why);
  };
}

}  // namespace spifit::cli
