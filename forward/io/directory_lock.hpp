#pragma once
// One writer per output directory: a run, fit, sweep or report holds DIR/.spifit-lock (an
// advisory flock(2) lock on it, which the kernel releases when the process ends, however it
// ends) for as long as it writes there. The file names the holder: pid, host and start time.
// A lock file whose holder is gone (a killed run) is taken over, and the holder it named is
// reported (taken_over()). Format: docs/reference/file-formats.md, "Output directories".
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace spifit::io {

class DirectoryLock {
 public:
  static constexpr const char* kFile = ".spifit-lock";

  // Who holds (or held) a lock, as its file says.
  struct Holder {
    long pid = 0;
    std::string host, started;  // started: UTC ISO 8601
    std::string describe() const;  // "pid 1234 on host h, since 2026-11-29T02:10:00Z"
  };

  // Why a lock could not be taken.
  struct Refusal {
    enum class Reason { held, permission_denied, cannot_create } reason = Reason::held;
    Holder holder;        // reason held: the live holder
    std::string message;  // the system's words otherwise
  };

  // Takes the lock of directory dir (which must exist). Null with *refusal set when another
  // process holds it or the lock file cannot be made.
  static std::unique_ptr<DirectoryLock> take(const std::filesystem::path& dir, Refusal* refusal);
  ~DirectoryLock();  // removes the lock file and releases the lock
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

  // The earlier holder this lock replaced: a process that ended without releasing it.
  const std::optional<Holder>& taken_over() const { return taken_over_; }

  // Removes the lock files this process holds, for a process about to end without running
  // destructors (std::_Exit after SIGINT or SIGTERM): the next run then finds no stale lock.
  static void release_all();

 private:
  DirectoryLock(std::filesystem::path file, int fd);
  std::filesystem::path file_;
  int fd_ = -1;
  std::optional<Holder> taken_over_;
};

}  // namespace spifit::io
