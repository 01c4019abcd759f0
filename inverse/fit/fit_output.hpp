#pragma once
// What `spifit fit` writes: DIR/fit.json (machines), DIR/card.toml (the fitted card; for a fit
// that is not usable DIR/card_NOT_USABLE.toml instead), DIR/experiments/NAME.csv (measured vs
// simulated at the start and at the solution), and the terse CLI table. Schema in
// docs/reference/file-formats.md.
#include "forward/io/output_directory.hpp"
#include "inverse/fit/fit_result.hpp"
#include "inverse/fit/fit_record.hpp"

#include <string>

namespace spifit::inverse {

// What fit.json holds for this fit (to_json(fit_record(...)) is the file's object).
FitRecord fit_record(const FitProblem& problem, const FitResult& result);

// "" for a usable fit, "_NOT_USABLE" otherwise: the end of the names of its card and exported
// decks (card.toml or card_NOT_USABLE.toml), so that a card from a fit that is not usable is
// never taken for a good one.
const char* fitted_file_suffix(bool usable);

// The fitted card with its own identity: named after the fit, its description and source saying
// it was fitted, and its [fitted] provenance (fit file, start card, data files, spifit version,
// date). date: UTC YYYY-MM-DD (fit_date()).
material::MaterialCard fitted_card(const FitProblem& problem, const FitResult& result, const std::string& date);
// Today's date, UTC, YYYY-MM-DD; the date of SOURCE_DATE_EPOCH (seconds since 1970, the
// reproducible-builds convention) when that is set, so that a rerun can give identical files.
std::string fit_date();

// Writes fit.json, the fitted card and experiments/*.csv; returns the card it wrote.
material::MaterialCard write_fit_outputs(const FitProblem& problem, const FitResult& result, const io::OutputDirectory& out);
std::string fit_table(const FitProblem& problem, const FitResult& result);

}  // namespace spifit::inverse
