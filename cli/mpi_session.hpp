#pragma once
// spifit under mpirun or srun (docs/guide/parallel-runs.md): rank 0 runs the command (fit,
// sweep) and hands its forward runs to the other ranks as jobs (inverse/runs/job_pool.hpp); ranks
// 1.. read the same fit or sweep file and answer jobs until rank 0 stops them. Without an MPI
// launcher (or in a build without Open MPI) this is one process: rank 0 of 1, no pool.
//
// Messages: rank 0 -> worker: a job or "stop"; worker -> rank 0: the job's answer, and "alive"
// every 2 s while it runs one (rank 0 counts a rank silent for 30 s as dead and gives its job to
// another). Only one thread of rank 0 (the pool's) calls MPI while the pool lives; both sides poll
// with a short sleep instead of blocking in MPI, so that an idle rank leaves its core to the runs.
#include "inverse/runs/job_pool.hpp"

#include <memory>

namespace spifit::cli::mpi {

// MPI_Init_thread when the environment says this process is one of an MPI job of more than one
// process; std::runtime_error when MPI cannot give the thread support the pool needs.
void start(int* argc, char*** argv);
// Rank 0: stops every worker (they return from serve()); then MPI_Finalize. Workers that never
// served wait for their stop first. Safe to call more than once and without start().
void finish();

int rank();
int size();
inline bool is_worker() { return rank() > 0; }

// Rank 0 of a job of more than one process: a pool of the other ranks (the same one on every
// call); null otherwise.
std::shared_ptr<inverse::JobPool> pool();
// Ranks 1..: answers jobs with handler until rank 0 stops this rank.
void serve(const inverse::JobHandler& handler);

// Ends the MPI job (and the MPI session) when main() returns or throws.
struct Session {
  Session(int* argc, char*** argv) { start(argc, argv); }
  ~Session() { finish(); }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

}  // namespace spifit::cli::mpi
