// The bundled scenes of a minute or more (label long): the line test on its half model, with the
// built-in and the G-code path, and the pie trade of cone50 on 90 deg (see
// golden_outputs_test.cpp).
#include "tests/support/golden_outputs.hpp"

TEST(GoldenOutputs, LongScenes) {
  spifit::test::check_golden_outputs({"experiments/aa3003o/scenes/line_half.toml", "experiments/aa3003o/scenes/line_half_gcode.toml",
                                      "experiments/aa3003o/scenes/cone50_pie90_10.toml"});
}
