#include "forward/scenes/common/run_heartbeat.hpp"

#include <cstdio>
#include <unistd.h>

namespace spifit::scene {

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

nlohmann::json RunHeartbeat::ended() const {
  nlohmann::json j = running();
  for (const char* k : {"pid", "host", "heartbeat", "heartbeat_interval"}) j.erase(k);
  return j;
}

void RunHeartbeat::stop() {
  const std::lock_guard<std::mutex> lock(mutex_);
  stopped_ = true;
}

}  // namespace spifit::scene
