#include "inverse/fit/fit_algorithms.hpp"

#include <nlopt.hpp>

namespace spifit::inverse {

const std::vector<FitAlgorithm>& fit_algorithms() {
  using E = FitAlgorithm::Engine;
  static const std::vector<FitAlgorithm> all{
      {"levenberg_marquardt", E::ceres}, {"dogleg", E::ceres},
      {"bobyqa", E::nlopt, false, nlopt::LN_BOBYQA},   {"cobyla", E::nlopt, false, nlopt::LN_COBYLA},
      {"nelder_mead", E::nlopt, false, nlopt::LN_NELDERMEAD}, {"sbplx", E::nlopt, false, nlopt::LN_SBPLX},
      {"direct_l", E::nlopt, true, nlopt::GN_DIRECT_L}, {"crs2", E::nlopt, true, nlopt::GN_CRS2_LM},
      {"isres", E::nlopt, true, nlopt::GN_ISRES},       {"mlsl", E::nlopt, true, nlopt::G_MLSL_LDS},
  };
  return all;
}

const FitAlgorithm* find_fit_algorithm(const std::string& name) {
  for (const auto& a : fit_algorithms())
    if (a.name == name) return &a;
  return nullptr;
}

const std::string& fit_algorithm_names() {
  static const std::string names = [] {
    std::string ceres, nlopt;
    for (const auto& a : fit_algorithms()) {
      std::string& s = a.engine == FitAlgorithm::Engine::ceres ? ceres : nlopt;
      s += (s.empty() ? "" : ", ") + a.name;
    }
    return ceres + " (Ceres); " + nlopt + " (NLopt)";
  }();
  return names;
}

bool is_fit_algorithm(const std::string& name) { return find_fit_algorithm(name) != nullptr; }

bool is_nlopt_algorithm(const std::string& name) {
  const FitAlgorithm* a = find_fit_algorithm(name);
  return a && a->engine == FitAlgorithm::Engine::nlopt;
}

}  // namespace spifit::inverse
