// The control of material_includes_element.cpp: the same layer's and the layers below it
// headers compile with the material library's include paths.
#include "forward/io/input_error.hpp"
#include "forward/material/hill48.hpp"

double layering_probe() { return 0.0; }
