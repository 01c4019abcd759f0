#include "forward/scenes/shell_benchmarks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace spifit::scene {
namespace {

struct Outcome {
  double value = 0.0, reference = 0.0;
  nlohmann::json details;
  solver::NewtonSummary summary;
};

Outcome run(const std::string& name, int mesh = 0, int points = 0) {
  ShellBenchmarkSetup s{name, mesh, points};
  ShellBenchmark b = make_shell_benchmark(s);
  solver::NewtonSolver solver(*b.model, *b.constraints, b.solver);
  Outcome o;
  o.summary = solver.solve();
  o.value = b.value(*b.model);
  o.reference = b.reference;
  if (b.details) o.details = b.details(*b.model);
  std::printf("%-26s mesh %3d: value %.6g reference %.6g ratio %.5f (%d increments, %d iterations) %s\n", name.c_str(), mesh,
              o.value, o.reference, o.value / o.reference, o.summary.increments, o.summary.iterations, o.details.dump().c_str());
  return o;
}

TEST(ShellBenchmarks, Explore) {
  const char* only = std::getenv("BENCH");
  for (const auto& n : shell_benchmark_names()) {
    if (only && n != only) continue;
    const int mesh = std::getenv("MESH") ? std::atoi(std::getenv("MESH")) : 0;
    run(n, mesh);
  }
}

}  // namespace
}  // namespace spifit::scene
