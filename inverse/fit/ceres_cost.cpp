#include "inverse/fit/ceres_cost.hpp"

#include "inverse/fit/exact_cost.hpp"
#include "inverse/fit/numeric_cost.hpp"

#include <type_traits>

namespace spifit::inverse {
namespace {

// One residual block per experiment; Ceres differentiates with Jet<double, kJetSize>.
struct ExperimentFunctor {
  const ParameterSet* parameters;
  const Experiment* experiment;
  std::atomic<long>* runs;
  template <typename T>
  bool operator()(T const* const* x, T* r) const {
    runs->fetch_add(1, std::memory_order_relaxed);
    if constexpr (std::is_same_v<T, double>) return experiment->residuals(parameters->point(x[0]), r);
    else return experiment->residuals(parameters->apply(x[0]), r);
  }
};

}  // namespace

// Exact derivatives through Jets where the experiment supports them, through the FE runs where
// they carry sensitivities, central differences (parallel, inside the bounds) for black boxes.
ceres::CostFunction* make_experiment_cost(const ParameterSet& ps, const Experiment& e, std::atomic<long>* runs) {
  if (!e.supports_jets() && e.exact_columns() > 0) return new ExactFeExperimentCost(&ps, &e, runs);
  if (!e.supports_jets()) return new NumericDiffExperimentCost(&ps, &e, runs);
  auto* cf = new ceres::DynamicAutoDiffCostFunction<ExperimentFunctor, kJetSize>(new ExperimentFunctor{&ps, &e, runs});
  cf->AddParameterBlock(ps.num_free());
  cf->SetNumResiduals(e.num_residuals());
  return cf;
}

}  // namespace spifit::inverse
