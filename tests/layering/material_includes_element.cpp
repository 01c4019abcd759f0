// Deliberately wrong: the material layer may not see the element layer above it. Built only by
// the test Layering.WrongIncludeFailsToCompile, which passes when the compiler cannot find the
// header.
#include "forward/element/shell_q4.hpp"
#include "forward/material/hill48.hpp"

double layering_probe() { return 0.0; }
