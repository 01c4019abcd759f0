#pragma once
// What `spifit fit` writes: DIR/fit.json (machines), DIR/card.toml (the fitted card),
// DIR/experiments/NAME.csv (measured vs simulated at the start and at the solution), and the
// terse CLI table. Schema in docs/file-formats.md.
#include "forward/io/output_directory.hpp"
#include "inverse/ceres_fit.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace spifit::inverse {

nlohmann::json fit_result_json(const FitProblem& problem, const FitResult& result);
void write_fit_outputs(const FitProblem& problem, const FitResult& result, const io::OutputDirectory& out);
std::string fit_table(const FitProblem& problem, const FitResult& result);

}  // namespace spifit::inverse
