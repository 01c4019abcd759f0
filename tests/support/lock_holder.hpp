#pragma once
// A child process that holds the lock of an output directory (forward/io/directory_lock.hpp)
// until it is killed: a live spifit run as another writer sees it.
#include "forward/io/directory_lock.hpp"

#include <csignal>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace spifit::test {

// A child process that holds the lock of `dir` until it is killed.
struct LockHolder {
  pid_t pid = -1;
  explicit LockHolder(const std::filesystem::path& dir) {
    int ready[2];
    if (::pipe(ready) != 0) return;
    pid = ::fork();
    if (pid == 0) {
      io::DirectoryLock::Refusal refusal;
      auto lock = io::DirectoryLock::take(dir, &refusal);
      const char ok = lock ? '1' : '0';
      (void)!::write(ready[1], &ok, 1);
      for (;;) ::pause();
    }
    char ok = '0';
    (void)!::read(ready[0], &ok, 1);
    ::close(ready[0]);
    ::close(ready[1]);
    if (ok != '1') pid = -1;
  }
  void kill() {
    if (pid <= 0) return;
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    pid = -1;
  }
  ~LockHolder() { kill(); }
};

}  // namespace spifit::test
