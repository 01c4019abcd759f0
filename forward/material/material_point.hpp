#pragma once
// One integration point with a committed state s0 and a trial state s1:
// update() computes s1 from s0; commit() accepts it once the global step converged;
// revert() discards it (line search, cut-back).
#include "forward/material/return_mapping.hpp"

namespace spifit::material {

template <typename T, int Dim>
class MaterialPoint {
 public:
  using Law = ReturnMapping<T, Dim>;
  using State = typename Law::State;
  using Vec = typename Law::Vec;
  using Mat = typename Law::Mat;

  explicit MaterialPoint(const Law& law) : law_(&law) {}

  UpdateResult update(const Vec& d_eps, Mat* tangent) {
    return law_->integrate(committed_, d_eps, trial_, tangent);
  }
  void commit() { committed_ = trial_; }
  void revert() { trial_ = committed_; }

  const State& committed() const { return committed_; }
  const State& trial() const { return trial_; }
  void set_committed(const State& s) { committed_ = trial_ = s; }
  const Law& law() const { return *law_; }

 private:
  const Law* law_;
  State committed_{}, trial_{};
};

}  // namespace spifit::material
