// `spifit status DIR`: what became of the run in an output directory (docs/reference/file-formats.md, "Run
// status"): its kind, scene and status; for a "running" summary whether the run is alive (its
// process exists on this host and its heartbeat is recent) or dead, and how to resume it.
// Exit codes: 0 ok or running and alive, 1 anything else (failed, interrupted, dead, ...),
// 2 not a spifit output directory.
#include "cli/commands.hpp"
#include "cli/progress_meter.hpp"

#include "forward/io/input_error.hpp"
#include "forward/scenes/common/run_heartbeat.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <sys/types.h>
#include <unistd.h>

namespace spifit::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string text_of(const json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : "";
}

double number_of(const json& j, const char* key, double otherwise) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : otherwise;
}

// fit, sweep, or the scene kind.
std::string kind_of(const json& j) {
  std::string kind = text_of(j, "kind");
  if (kind.empty() && j.contains("fit_file")) kind = "fit";  // the running summary of an older spifit's fit
  return kind.empty() ? "unknown" : kind;
}

// The scene (fit, sweep) by name, with its file.
std::string scene_of(const json& j) {
  std::string name = text_of(j, "scene");
  if (name.empty()) name = text_of(j, "fit");
  if (name.empty()) name = text_of(j, "sweep");
  std::string file = text_of(j, "scene_file");
  if (file.empty()) file = text_of(j, "fit_file");
  if (file.empty()) file = text_of(j, "sweep_file");
  if (name.empty()) return file.empty() ? "unknown" : file;
  return file.empty() ? name : name + " (" + file + ")";
}

// How to go on from where the run ended.
std::string resume_hint(const json& j, const std::string& dir) {
  const std::string scene = text_of(j, "scene_file"), fit = text_of(j, "fit_file");
  std::error_code ec;
  if (!scene.empty() && fs::exists(fs::path(dir) / "checkpoint" / "state.bin", ec))
    return "resume with spifit run " + scene + " --out " + dir + " --resume";
  if (!fit.empty() && fs::exists(fs::path(dir) / "runs" / "evaluations.jsonl", ec))
    return "resume with spifit fit " + fit + " --out " + dir + " --resume";
  return "no checkpoint to resume from: run it again with --force";
}

// "progress: 120 increments, tool travel 45.2 of 300 mm, 2 of 4 marks" from the running
// summary's progress, or a final summary's counts; "" when there is nothing.
std::string progress_of(const json& j) {
  const json p = j.contains("progress") && j["progress"].is_object() ? j["progress"] : j;
  std::string out;
  auto add = [&out](const std::string& s) { out += (out.empty() ? "" : ", ") + s; };
  if (p.contains("increments") && p["increments"].is_number()) add(std::to_string(p["increments"].get<long>()) + " increments");
  if (p.contains("travel_reached") && p["travel_reached"].is_number()) {
    char buf[80];
    std::snprintf(buf, sizeof buf, "tool travel %.2f", p["travel_reached"].get<double>());
    std::string s = buf;
    double total = number_of(p, "travel", -1.0);
    if (total < 0.0 && j.contains("tool") && j["tool"].is_object()) total = number_of(j["tool"], "travel", -1.0);
    if (total >= 0.0) {
      std::snprintf(buf, sizeof buf, " of %.2f", total);
      s += buf;
    }
    add(s + " mm");
  }
  if (p.contains("marks_reached") && p["marks_reached"].is_number())
    add(std::to_string(p["marks_reached"].get<long>()) + (p.contains("marks") ? " of " + std::to_string(p["marks"].get<long>()) : "") + " marks");
  // A fit: its iteration, where it is among the iteration's FE runs, and the time left of it.
  if (p.contains("iteration") && p["iteration"].is_number()) {
    std::string s = (p.contains("phase") && p["phase"].is_string() ? p["phase"].get<std::string>() + ": " : "") + "iteration " +
                    std::to_string(p["iteration"].get<long>());
    if (p.contains("cost") && p["cost"].is_number()) {
      char buf[64];
      std::snprintf(buf, sizeof buf, ", cost %.6g", p["cost"].get<double>());
      s += buf;
    }
    if (p.contains("iteration_runs") && p["iteration_runs"].is_number()) {
      const long done = p["iteration_runs"].get<long>(), of = p.contains("iteration_runs_expected") ? p["iteration_runs_expected"].get<long>() : 0;
      s += ", " + std::to_string(done) + (of > 0 && done <= of ? " of " + std::to_string(of) : "") + " FE runs of it done";
      if (p.contains("iteration_seconds_left") && p["iteration_seconds_left"].is_number())
        s += ", about " + clock_time(p["iteration_seconds_left"].get<double>()) + " left in it";
    }
    add(s);
  }
  if (p.contains("forward_runs") && p["forward_runs"].is_number()) add(std::to_string(p["forward_runs"].get<long>()) + " forward runs");
  if (p.contains("runs_done") && p["runs_done"].is_number()) add(std::to_string(p["runs_done"].get<long>()) + " runs done");
  return out;
}

// The verdict on a running summary: its line and whether the run is alive.
struct Liveness {
  bool alive = false;
  std::string line;
};

Liveness liveness(const json& j, const std::string& dir, std::time_t now) {
  const auto pid_it = j.find("pid");
  if (pid_it == j.end() || !pid_it->is_number_integer())
    return {false, "unknown: the summary has no pid (written by a spifit without heartbeats): the run is alive only if a spifit process "
                   "still writes to " + dir};
  const long long pid = pid_it->get<long long>();
  const std::string host = text_of(j, "host"), here = scene::host_name();
  const double interval = number_of(j, "heartbeat_interval", scene::kHeartbeatSeconds);
  const double limit = 3.0 * interval + 60.0;
  std::time_t beat = 0;
  const bool has_beat = scene::parse_utc_iso(text_of(j, "heartbeat"), &beat);
  const double age = has_beat ? std::difftime(now, beat) : -1.0;
  const bool fresh = has_beat && age <= limit;
  const std::string ago = has_beat ? "last heartbeat " + io::format_number(std::max(0.0, age)) + " s ago" : "no heartbeat";
  if (host != here) {
    const std::string where = "on host " + (host.empty() ? std::string("(unknown)") : host) + ", not this one (" + here + ")";
    if (fresh) return {true, "alive: pid " + std::to_string(pid) + " " + where + ", " + ago};
    return {false, "dead, most likely: pid " + std::to_string(pid) + " " + where + ", " + ago + " (more than " + io::format_number(limit) +
                       " s): " + resume_hint(j, dir)};
  }
  const bool exists = pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
  if (!exists) return {false, "dead: the process " + std::to_string(pid) + " is gone: the run was killed; " + resume_hint(j, dir)};
  if (!fresh)
    return {false, "not responding: the process " + std::to_string(pid) + " exists, " + ago + " (more than " + io::format_number(limit) +
                       " s): it is stopped or hung, or the pid now belongs to another process"};
  return {true, "alive: pid " + std::to_string(pid) + " on this host, " + ago + ", started " + text_of(j, "started")};
}

}  // namespace

void add_status_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  auto dir = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand("status", "Kind, scene and status of the run in an output directory; for a running one, whether it is alive "
                                           "(exit 0 ok or alive, 1 failed, interrupted or dead, 2 not a spifit output directory)");
  cmd->add_option("DIR", *dir, "output directory of spifit run, fit or sweep")->required();
  cmd->callback([dir, &g, &exit_code] {
    const fs::path file = fs::path(*dir) / "summary.json";
    std::ifstream in(file);
    json j;
    if (in) {
      std::stringstream ss;
      ss << in.rdbuf();
      j = json::parse(ss.str(), nullptr, false);
    }
    if (!in || !j.is_object() || !j.contains("status") || !j["status"].is_string()) {
      std::cerr << "spifit: " << *dir << ": not a spifit output directory ("
                << (!in ? "no summary.json" : "summary.json is not a spifit summary") << ")\n";
      exit_code = 2;
      return;
    }
    const std::string status = j["status"].get<std::string>();
    std::string line = status;
    bool good = status == "ok";
    if (status == "running") {
      const Liveness l = liveness(j, *dir, std::time(nullptr));
      good = l.alive;
      line += ", " + l.line;
    } else if (status == "interrupted") {
      line += ": " + text_of(j, "message");
      if (line.find("resume with") == std::string::npos && line.find("--force") == std::string::npos) line += "; " + resume_hint(j, *dir);
    } else if (status != "ok" && j.contains("message")) {
      line += ": " + text_of(j, "message");
    }
    exit_code = good ? 0 : 1;
    if (g.quiet) return;
    std::cout << "kind: " << kind_of(j) << "\nscene: " << scene_of(j) << "\nstatus: " << line << "\n";
    const std::string progress = progress_of(j);
    if (!progress.empty()) std::cout << "progress: " << progress << "\n";
  });
}

}  // namespace spifit::cli
