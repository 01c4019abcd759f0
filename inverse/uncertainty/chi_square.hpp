#pragma once
// The chi-square distribution's upper tail: how likely n independent standard-normal residuals
// give a sum of squares at least x, and the x exceeded with a given probability. The fit's
// verdicts compare residuals with the stated measurement noise by it (fit_assessment.hpp).
namespace spifit::inverse {

// P(chi2_n >= x) for n degrees of freedom (n > 0, x >= 0): the regularised upper incomplete gamma
// Q(n/2, x/2).
double chi_square_upper_tail(int n, double x);

// The x with P(chi2_n >= x) = tail (0 < tail < 1), to about 1e-10 relative.
double chi_square_upper_quantile(int n, double tail);

}  // namespace spifit::inverse
