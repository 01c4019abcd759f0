#include "forward/io/directory_lock.hpp"

#include "forward/io/host_and_time.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <mutex>
#include <set>
#include <sstream>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace spifit::io {
namespace {

// The lock files this process holds (release_all).
std::mutex g_held_mutex;
std::set<std::filesystem::path> g_held;

// The holder a lock file names ("pid = N", "host = H", "started = T" lines); pid 0 if unreadable.
DirectoryLock::Holder read_holder(int fd) {
  std::string text;
  char buf[512];
  ::lseek(fd, 0, SEEK_SET);
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
  DirectoryLock::Holder h;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find(" = ");
    if (eq == std::string::npos) continue;
    const std::string key = line.substr(0, eq), value = line.substr(eq + 3);
    if (key == "pid") h.pid = std::strtol(value.c_str(), nullptr, 10);
    if (key == "host") h.host = value;
    if (key == "started") h.started = value;
  }
  return h;
}

}  // namespace

DirectoryLock::DirectoryLock(std::filesystem::path file, int fd) : file_(std::move(file)), fd_(fd) {
  const std::lock_guard<std::mutex> lock(g_held_mutex);
  g_held.insert(file_);
}

void DirectoryLock::release_all() {
  const std::lock_guard<std::mutex> lock(g_held_mutex);
  std::error_code ec;
  for (const auto& f : g_held) std::filesystem::remove(f, ec);
  g_held.clear();
}

std::string DirectoryLock::Holder::describe() const {
  std::string s = "pid " + std::to_string(pid);
  if (!host.empty()) s += " on host " + host;
  if (!started.empty()) s += ", since " + started;
  return s;
}

std::unique_ptr<DirectoryLock> DirectoryLock::take(const std::filesystem::path& dir, Refusal* refusal) {
  const std::filesystem::path file = dir / kFile;
  // The lock file is removed when its holder releases it: a lock taken on a file that was
  // removed (and perhaps made again by a third process) in between is no lock, so take it again.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
      const int err = errno;
      refusal->reason = err == EACCES || err == EPERM || err == EROFS ? Refusal::Reason::permission_denied : Refusal::Reason::cannot_create;
      refusal->message = std::strerror(err);
      return nullptr;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      refusal->holder = read_holder(fd);
      ::close(fd);
      if (err == EWOULDBLOCK) {
        refusal->reason = Refusal::Reason::held;
      } else {
        refusal->reason = Refusal::Reason::cannot_create;
        refusal->message = std::strerror(err);
      }
      return nullptr;
    }
    struct stat held {}, now {};
    if (::fstat(fd, &held) != 0 || ::stat(file.c_str(), &now) != 0 || held.st_ino != now.st_ino || held.st_dev != now.st_dev) {
      ::close(fd);
      continue;
    }
    std::unique_ptr<DirectoryLock> lock(new DirectoryLock(file, fd));
    const Holder before = read_holder(fd);
    if (before.pid != 0) lock->taken_over_ = before;
    const std::string text = "# spifit: this directory is being written by the process below (docs/reference/file-formats.md)\n"
                             "pid = " + std::to_string(::getpid()) + "\nhost = " + host_name() + "\nstarted = " + utc_iso(std::time(nullptr)) + "\n";
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size())) {
      const int err = errno;
      refusal->reason = err == EACCES || err == EPERM || err == EROFS ? Refusal::Reason::permission_denied : Refusal::Reason::cannot_create;
      refusal->message = std::strerror(err);
      return nullptr;  // the destructor removes the file and releases the lock
    }
    return lock;
  }
  refusal->reason = Refusal::Reason::cannot_create;
  refusal->message = "the lock file keeps being replaced";
  return nullptr;
}

DirectoryLock::~DirectoryLock() {
  if (fd_ < 0) return;
  {
    const std::lock_guard<std::mutex> lock(g_held_mutex);
    g_held.erase(file_);
  }
  std::error_code ec;
  std::filesystem::remove(file_, ec);  // while still holding it: nobody else has it now
  ::close(fd_);
}

}  // namespace spifit::io
