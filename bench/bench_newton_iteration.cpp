// Time of ONE Newton iteration of the implicit shell solver (goal for 50x50: < 0.2 s
// on 2 cores): assembly of the reduced residual + tangent, numeric sparse factorisation
// (symbolic analysis already done) and solve, on a PLASTIC plate. Setup, outside the timed
// loop: square plate 100 x 100 mm, t = 1.2 mm, 5 thickness points, AA3003-O card C.3 + C.4,
// clamped edges, centre pushed down 8 mm x load factor, solved to load factor 0.5 (UMFPACK),
// then one untimed warm-up iteration with the benchmarked solver. Counters: elements, DOFs,
// reduced unknowns, nnz of the tangent, and the split assembly_s / linear_s per iteration.
// Run with OMP_NUM_THREADS=1 or 2; the growth with the mesh is printed at exit.
#include "forward/mesh/square_sheet.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/newton_solver.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace spifit;

namespace {

constexpr double kDepth = 8.0;   // mm, centre displacement at load factor 1
constexpr double kLambda = 0.5;  // load factor of the plastic state that is timed

struct Case {  // mesh outlives model, model outlives solver
  int n = 0;
  mesh::Mesh mesh;
  std::unique_ptr<model::ShellModel> model;
  std::unique_ptr<solver::DofConstraints> constraints;
  std::string error;  // empty when converged and plastic
};

// Builds and pre-solves the n x n plate once; the two solvers of one size share it.
Case& plastic_plate(int n) {
  static std::unique_ptr<Case> c;
  if (c && c->n == n) return *c;
  c = std::make_unique<Case>();
  c->n = n;
  mesh::SquareSheetOptions sheet;
  sheet.length_x = sheet.length_y = 100.0;
  sheet.nx = sheet.ny = n;
  c->mesh = mesh::square_sheet(sheet);
  material::MaterialParams<double> p;  // E, nu, Swift: card C.4 = defaults
  p.F = 1.224; p.G = 1.193; p.H = 0.807; p.N = p.L = p.M = 4.06;  // card C.3
  model::ShellModelOptions mo;
  mo.shell.thickness_points = 5;
  c->model = std::make_unique<model::ShellModel>(c->mesh, 1.2, p, mo);
  auto& m = *c->model;
  c->constraints = std::make_unique<solver::DofConstraints>(m.num_dofs());
  for (int node : c->mesh.node_sets.at("boundary"))
    for (int k = 0; k < 6; ++k) c->constraints->prescribe(model::ShellModel::dof(node, k), 0.0);
  c->constraints->prescribe(model::ShellModel::dof(c->mesh.node_sets.at("centre").front(), 2), -kDepth);
  c->constraints->finalize();
  solver::NewtonSolver s(m, *c->constraints, {.initial_increment = 0.1, .max_increment = 0.25});
  const auto summary = s.solve(kLambda);
  int plastic = 0;
  for (int e = 0; e < m.num_elements(); ++e)
    for (int q = 0; q < m.element(e).points(); ++q)
      for (int l = 0; l < m.element(e).section(q).layers(); ++l)
        if (m.element(e).section(q).layer_state(l).eqps > 0.0) ++plastic;
  if (!summary.converged) c->error = "pre-solve did not converge: " + summary.message;
  else if (plastic == 0) c->error = "plate not plastic at the timed state";
  std::printf("# %dx%d: pre-solve to lambda %.2f: %d increments, %d iterations, %d plastic layer points\n",
              n, n, kLambda, summary.counters.increments, summary.counters.iterations, plastic);
  return *c;
}

std::map<std::pair<std::string, int>, double> g_median;  // (solver, n) -> s per iteration

void newton_iteration(benchmark::State& state, const char* name, solver::LinearSolverKind kind) {
  const int n = static_cast<int>(state.range(0));
  Case& c = plastic_plate(n);
  if (!c.error.empty()) return state.SkipWithError(c.error.c_str());
  solver::NewtonSolver s(*c.model, *c.constraints, {.linear_solver = kind});
  Eigen::VectorXd du;
  const solver::SparseMatrix* matrix = nullptr;
  solver::LinearSolver& linear = s.linear_solver(&matrix);  // kind is fixed: the same solver every iteration
  auto iterate = [&](double* t_asm, double* t_lin) {
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    const auto a = s.assemble(kLambda, true, nullptr);
    const auto t1 = clock::now();
    const bool ok = a.failure.ok && linear.factorize(*matrix) && linear.solve(-a.residual, &du);
    const auto t2 = clock::now();
    benchmark::DoNotOptimize(du.data());
    *t_asm += std::chrono::duration<double>(t1 - t0).count();
    *t_lin += std::chrono::duration<double>(t2 - t1).count();
    return ok;
  };
  double t_asm = 0.0, t_lin = 0.0;  // warm-up (symbolic analysis), untimed
  if (!iterate(&t_asm, &t_lin)) return state.SkipWithError(("warm-up failed: " + linear.error()).c_str());
  t_asm = t_lin = 0.0;
  std::vector<double> per_iteration;
  for (auto _ : state) {
    const double before = t_asm + t_lin;
    if (!iterate(&t_asm, &t_lin)) return state.SkipWithError(("iteration failed: " + linear.error()).c_str());
    per_iteration.push_back(t_asm + t_lin - before);
  }
  std::sort(per_iteration.begin(), per_iteration.end());
  const std::size_t k = per_iteration.size();
  const double median = k % 2 ? per_iteration[k / 2] : 0.5 * (per_iteration[k / 2 - 1] + per_iteration[k / 2]);
  const double its = static_cast<double>(state.iterations());
  state.counters["elements"] = static_cast<double>(c.model->num_elements());
  state.counters["dofs"] = static_cast<double>(c.model->num_dofs());
  state.counters["reduced"] = static_cast<double>(c.constraints->num_reduced());
  state.counters["nnz"] = static_cast<double>(s.tangent().pattern().nonzeros());
  state.counters["threads"] = static_cast<double>(omp_get_max_threads());
  state.counters["assembly_s"] = t_asm / its;
  state.counters["linear_s"] = t_lin / its;
  state.counters["median_s"] = median;
  g_median[{name, n}] = median;
}

void register_all() {
  for (int n : {50, 100, 200}) {
    for (auto [name, kind] : {std::pair{"umfpack", solver::LinearSolverKind::umfpack},
                              std::pair{"cholmod", solver::LinearSolverKind::cholmod}}) {
      auto* b = benchmark::RegisterBenchmark((std::string("newton_iteration/") + name).c_str(), newton_iteration, name, kind);
      b->Arg(n)->Unit(benchmark::kMillisecond)->UseRealTime();
      b->Iterations(n == 50 ? 10 : n == 100 ? 5 : 3);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  // Growth: time per iteration relative to 50x50 (4x elements per step; linear growth = 4x).
  std::printf("\n# growth (assembly + factorise + solve, median of the timed iterations)\n");
  for (const char* name : {"umfpack", "cholmod"}) {
    const auto ref = g_median.find({name, 50});
    for (int n : {50, 100, 200}) {
      const auto it = g_median.find({name, n});
      if (it == g_median.end()) continue;
      std::printf("# %-8s %3dx%-3d %9.1f ms", name, n, n, 1e3 * it->second);
      if (ref != g_median.end()) std::printf("  x%.2f vs 50x50", it->second / ref->second);
      std::printf("\n");
    }
  }
  return 0;
}
