#pragma once
// Forward runs handed to other processes (docs/design/parallel-runs.md): an MPI job of
// `spifit fit` or `spifit sweep` has its rank 0 run the optimiser or the sweep and its other
// ranks run the forward runs. What travels is a job (bytes: what to run, with the exact bits of
// every number) and its answer (bytes: the numbers the run gave), so a run gives the same answer
// on whichever process it ran, and the fit or sweep takes the same steps as a serial one.
#include <functional>
#include <string>

namespace spifit::inverse {

class JobPool {
 public:
  virtual ~JobPool() = default;
  // Processes that run jobs (at least 1).
  virtual int workers() const = 0;
  // Runs a job on a free worker and returns its answer. Thread-safe: as many jobs run at once as
  // there are workers, the others wait their turn (first come, first served).
  virtual std::string run(const std::string& job) = 0;
};

// What a worker does with a job: its answer (a JobHandler never throws; a failed run is an
// answer that says so).
using JobHandler = std::function<std::string(const std::string& job)>;

}  // namespace spifit::inverse
