#pragma once
// The algorithms a fit can use, by the name a fit file's `algorithm` or `--algorithm` gives:
// Ceres's trust-region least squares (levenberg_marquardt, dogleg) and NLopt's local
// derivative-free and global optimisers (docs/design/identification.md). One table: the fit
// file, the CLI, run_fit and the NLopt driver all read it.
#include <string>
#include <vector>

namespace spifit::inverse {

struct FitAlgorithm {
  enum class Engine { ceres, nlopt };
  std::string name;
  Engine engine;
  bool global = false;  // NLopt's global optimisers
  int nlopt_code = -1;  // nlopt::algorithm, NLopt only
};

// In the order of fit_algorithm_names().
const std::vector<FitAlgorithm>& fit_algorithms();
const FitAlgorithm* find_fit_algorithm(const std::string& name);
// "levenberg_marquardt, dogleg (Ceres); bobyqa, ... (NLopt)"
const std::string& fit_algorithm_names();
bool is_fit_algorithm(const std::string& name);
bool is_nlopt_algorithm(const std::string& name);

}  // namespace spifit::inverse
