#pragma once
// Sections of the fit report (fit_document.cpp): which experiment informs which parameter, and
// the forward runs and wall time per experiment and per FE scene file.
#include "inverse/fit/fit_record.hpp"
#include "reports/report_document.hpp"

namespace spifit::reports {

// "Which experiment informs which parameter": per experiment and free parameter its share of the
// parameter's Fisher information at the solution (fit.json information_share); nothing when
// fit.json has no shares.
void add_information_shares(Document& d, const inverse::FitRecord& record);

// "Forward runs": per experiment its evaluations, the scene runs it asked for and their wall
// time; per FE scene file its runs, failures, retries and run times. A fit.json without these
// counts (an older spifit) gets a sentence instead of the tables.
void add_forward_runs(Document& d, const inverse::FitRecord& record);

}  // namespace spifit::reports
