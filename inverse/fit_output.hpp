#pragma once
// What `spifit fit` writes: DIR/fit.json (machines), DIR/card.toml (the fitted card),
// DIR/experiments/NAME.csv (measured vs simulated at the start and at the solution), and the
// terse CLI table. Schema in docs/reference/file-formats.md.
#include "forward/io/output_directory.hpp"
#include "inverse/fit_result.hpp"
#include "inverse/fit_record.hpp"

#include <string>

namespace spifit::inverse {

// What fit.json holds for this fit (to_json(fit_record(...)) is the file's object).
FitRecord fit_record(const FitProblem& problem, const FitResult& result);
void write_fit_outputs(const FitProblem& problem, const FitResult& result, const io::OutputDirectory& out);
std::string fit_table(const FitProblem& problem, const FitResult& result);

}  // namespace spifit::inverse
