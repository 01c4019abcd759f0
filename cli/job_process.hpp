#pragma once
// A worker rank's forward runs in processes of their own (docs/guide/parallel-runs.md, "A run
// that dies"): each job is answered by a child `spifit job ...` that reads the job on stdin and
// writes the answer on stdout. A run that crashes, is killed or runs out of memory takes its
// child with it, not the rank or the MPI job: the job runs once more, and if its process dies
// again the answer says so (a failed forward run, which fits and sweeps survive).
#include "inverse/runs/job_pool.hpp"

#include <functional>
#include <string>
#include <vector>

namespace spifit::cli {

struct ChildOutcome {
  bool ok = false;     // exited with status 0
  std::string output;  // its stdout
  std::string why;     // otherwise: "killed by signal 9", "exit status 2: <first line of stderr>", ...
};

// Runs this executable (/proc/self/exe) with args, input on its stdin; kills it after
// kill_after_seconds (0: never). The child dies with its parent (PR_SET_PDEATHSIG).
ChildOutcome run_child(const std::vector<std::string>& args, const std::string& input, double kill_after_seconds);

// A JobHandler that answers each job by run_child(args, job, kill_after_seconds), twice at most;
// failed(job, why) is the answer when both attempts died. note(why) is told of each death.
inverse::JobHandler jobs_in_child_processes(std::vector<std::string> args, double kill_after_seconds,
                                            std::function<std::string(const std::string& job, const std::string& why)> failed,
                                            std::function<void(const std::string& why)> note);

}  // namespace spifit::cli
