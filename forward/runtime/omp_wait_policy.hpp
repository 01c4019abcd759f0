#pragma once
// OpenMP idle threads that spin (libgomp's default while OMP_WAIT_POLICY is unset) slowed the
// serial sparse factorisation between the parallel element loops by up to 2x on the 2-core
// test machine (indent: linear solver 0.53 s spinning vs 0.28 s passive; docs/design/decisions.md).
// The runtime reads the policy once, before main, so an executable that wants the passive
// policy re-executes itself with OMP_WAIT_POLICY=passive. A policy set by the user is kept.
namespace spifit::runtime {

// Call first thing in main. Returns only if nothing had to change or the re-execution failed
// (then the run goes on with the default policy).
void ensure_passive_omp_wait(char** argv);

}  // namespace spifit::runtime
