#pragma once
// What the commands that run long work share: a failure written into summary.json before it goes
// on, and the command line and stderr notes of a worker rank's job processes.
#include "cli/commands.hpp"
#include "cli/run_signals.hpp"
#include "forward/scenes/common/run_heartbeat.hpp"
#include "forward/scenes/common/run_status.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace spifit::cli {

// Runs f; an exception ends the watch and leaves summary.json with status "failed" and the
// exception's message (not "running" with a heartbeat that stops) before it goes on.
template <typename F>
auto failed_on_error(scene::RunHeartbeat& heartbeat, RunWatch& watch, F f) {
  try {
    return f();
  } catch (const std::exception& e) {
    watch.stop();
    nlohmann::json j = heartbeat.ended();
    j["status"] = scene::to_string(scene::RunStatus::failed);
    j["message"] = e.what();
    heartbeat.finish(j);
    throw;
  }
}

// The command line of a worker rank's job process: quiet, the rank's --threads.
std::vector<std::string> job_args(const GlobalOptions& g, std::vector<std::string> command);
// One line on stderr naming this MPI rank.
void note_on_stderr(const std::string& why);

}  // namespace spifit::cli
