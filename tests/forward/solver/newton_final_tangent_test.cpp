// NewtonOptions::skip_final_tangent: an iterate predicted to end its increment is assembled
// without the tangent. The run must be the same, bit for bit, as one that assembles every
// tangent, with fewer tangents assembled.
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/mesh/benchmark_meshes.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/solver/convergence_test.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>

namespace spifit::solver {
namespace {

struct PlasticStripRun {
  NewtonCounters counters;
  std::vector<double> tip;  // z of the tip centre after each increment
};

// A plastic cantilever strip (10 x 1 x 1, 10 x 2 elements, Swift hardening) under a tip load
// in ten increments, to the scene tolerances.
PlasticStripRun plastic_strip(bool skip_final_tangent) {
  const mesh::Mesh mesh = mesh::strip(10.0, 1.0, 10, 2);
  material::MaterialParams<double> p;
  p.E = 70000.0; p.nu = 0.3; p.hardening[material::SwiftHardening::K] = 100.0; p.hardening[material::SwiftHardening::eps0] = 0.001; p.hardening[material::SwiftHardening::n] = 0.2; p.plastic = true;
  model::ShellModel model(mesh, 1.0, p, {});
  DofConstraints constraints(model.num_dofs());
  for (int n : mesh.node_sets.at("clamped"))
    for (int k = 0; k < 6; ++k) constraints.prescribe(model::ShellModel::dof(n, k));
  for (int n : mesh.node_sets.at("tip")) model.add_nodal_load(model::ShellModel::dof(n, 2), 1.0);
  constraints.finalize();
  NewtonOptions o;
  o.initial_increment = o.max_increment = 0.1;
  o.force_tolerance = o.displacement_tolerance = 1e-5;
  o.skip_final_tangent = skip_final_tangent;
  NewtonSolver s(model, constraints, o);
  PlasticStripRun run;
  const int tip = mesh.node_sets.at("tip_centre")[0];
  const NewtonSummary summary = s.solve(1.0, [&](const IncrementReport&) {
    run.tip.push_back(model.displacement(tip).z());
    return true;
  });
  EXPECT_TRUE(summary.converged) << summary.message;
  run.counters = summary.counters;
  return run;
}

TEST(NewtonFinalTangent, SkippingItGivesTheSameRunWithFewerTangents) {
  const PlasticStripRun all = plastic_strip(false), skip = plastic_strip(true);
  ASSERT_EQ(all.tip.size(), skip.tip.size());
  for (std::size_t i = 0; i < all.tip.size(); ++i) EXPECT_EQ(all.tip[i], skip.tip[i]) << "increment " << i + 1;
  EXPECT_EQ(all.counters.iterations, skip.counters.iterations);
  EXPECT_EQ(all.counters.factorisations(), skip.counters.factorisations());
  EXPECT_EQ(all.counters.residual_assemblies, 0);
  EXPECT_EQ(all.counters.tangent_reassemblies, 0);
  // Every skipped tangent is an assembly the full run made with one; a wrong prediction costs
  // one more assembly, with the tangent.
  EXPECT_GT(skip.counters.residual_assemblies, 0);
  EXPECT_EQ(skip.counters.tangent_assemblies + skip.counters.residual_assemblies - skip.counters.tangent_reassemblies,
            all.counters.tangent_assemblies);
  EXPECT_LT(skip.counters.tangent_assemblies, all.counters.tangent_assemblies);
}

// The prediction's rule on numbers: the residual extrapolated at the last rate must pass the
// force test, and the correction (or the next one extrapolated, with the estimate) the
// displacement test.
TEST(NewtonFinalTangent, LikelyFinalNeedsBothTestsPredictedToPass) {
  NewtonOptions o;
  o.force_tolerance = o.displacement_tolerance = 1e-5;
  const ConvergenceTest test(o, 1.0, false);
  EXPECT_TRUE(test.likely_final(1e-4, 1e-2, 0.5e-5, 1.0));    // residual 1e-6 predicted, correction passes
  EXPECT_FALSE(test.likely_final(1e-4, 5e-4, 0.5e-5, 1.0));   // residual 2e-5 predicted
  EXPECT_FALSE(test.likely_final(1e-4, 1e-2, 2e-5, 1.0));     // the correction fails the displacement test
  EXPECT_FALSE(test.likely_final(1e-4, 1e-5, 1e-7, 1.0));     // residual growing
  EXPECT_FALSE(test.likely_final(1e-4, 0.0, 1e-7, 1.0));      // no rate yet
  o.estimate_next_correction = true;
  const ConvergenceTest estimating(o, 1.0, false);
  EXPECT_TRUE(estimating.likely_final(1e-4, 1e-2, 2e-5, 1.0));  // next correction 2e-7 predicted
}

}  // namespace
}  // namespace spifit::solver
