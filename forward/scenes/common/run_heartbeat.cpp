#include "forward/scenes/common/run_heartbeat.hpp"

#include <cstdio>
#include <unistd.h>

namespace spifit::scene {

std::string utc_iso(std::time_t t) {
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

bool parse_utc_iso(const std::string& text, std::time_t* t) {
  std::tm tm{};
  char z = 0;
  if (std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d%c", &tm.tm_year, &tm.tm_mon, &tm.tm_mday, &tm.tm_hour, &tm.tm_min, &tm.tm_sec, &z) != 7 ||
      z != 'Z')
    return false;
  tm.tm_year -= 1900;
  tm.tm_mon -= 1;
  *t = timegm(&tm);
  return *t != static_cast<std::time_t>(-1);
}

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "";
  return buf;
}

RunHeartbeat::RunHeartbeat(RunFiles files, nlohmann::json running, double interval_seconds)
    : files_(files),
      running_(std::move(running)),
      interval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(interval_seconds))),
      last_(std::chrono::steady_clock::now().time_since_epoch().count()) {
  running_["status"] = "running";
  running_["pid"] = static_cast<long long>(getpid());
  running_["host"] = host_name();
  running_["started"] = utc_iso(std::time(nullptr));
  running_["heartbeat"] = running_["started"];
  running_["heartbeat_interval"] = interval_seconds;
}

void RunHeartbeat::write() {
  const std::lock_guard<std::mutex> lock(mutex_);
  write_locked();
}

void RunHeartbeat::write_locked() {
  last_ = std::chrono::steady_clock::now().time_since_epoch().count();
  if (stopped_ || !files_.enabled()) return;  // a run in memory: nothing to write
  running_["heartbeat"] = utc_iso(std::time(nullptr));
  files_.write("summary.json", running_.dump(2) + "\n");
}

void RunHeartbeat::beat(nlohmann::json progress) {
  if (!due()) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  running_["progress"] = std::move(progress);
  write_locked();
}

bool RunHeartbeat::finish(const nlohmann::json& final) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (stopped_) return false;
  stopped_ = true;
  files_.write("summary.json", final.dump(2) + "\n");
  return true;
}

nlohmann::json RunHeartbeat::running() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return running_;
}

void RunHeartbeat::stop() {
  const std::lock_guard<std::mutex> lock(mutex_);
  stopped_ = true;
}

}  // namespace spifit::scene
