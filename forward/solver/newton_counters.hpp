#pragma once
// Totals of a Newton run: one struct carried by the stepping state (checkpoints), the summary of
// a solve and the callers that add up several solves.

namespace spifit::solver {

struct NewtonCounters {
  int increments = 0;  // converged increments
  int iterations = 0;  // Newton iterations, of failed attempts too
  int cutbacks = 0;    // failed increment attempts
  // Numeric factorisations by solver, and symbolic analyses (fill-reducing orderings), counted
  // over the life of the solver objects (and of a restored state's).
  int cholmod_factorisations = 0, umfpack_factorisations = 0, symbolic_analyses = 0;
  // Stabilised increments (NewtonOptions::stabilisation): how many converged, the viscous work
  // they dissipated in all, and the largest relative out-of-balance one was accepted with.
  int stabilised_increments = 0;
  double viscous_work = 0.0, max_viscous_force = 0.0;
  // Wall seconds by phase, over the solver's life (profile, not results): parallel element
  // evaluation, serial assembly in element order, factorisation and solve.
  double element_seconds = 0.0, scatter_seconds = 0.0, linear_seconds = 0.0;
  // Assemblies of the residual with and without the tangent, and how often an iterate predicted
  // to end its increment did not (its tangent then assembled after all: NewtonSolver::increment).
  int tangent_assemblies = 0, residual_assemblies = 0, tangent_reassemblies = 0;

  int factorisations() const { return cholmod_factorisations + umfpack_factorisations; }
};

}  // namespace spifit::solver
