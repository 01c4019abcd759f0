// The bundled short scenes write the outputs of tests/golden/scene_outputs.json (every CSV and
// VTU file byte for byte, summaries to 1e-12): a guard through restructurings. Correctness is
// checked against closed forms, published values and fine references elsewhere.
#include "tests/support/golden_outputs.hpp"

TEST(GoldenOutputs, MaterialPointScenes) {
  std::vector<std::string> scenes;
  for (const char* n : {"tensile_00", "tensile_00_af", "tensile_00_ziegler", "tensile_45", "tensile_45_af", "tensile_90", "tensile_90_af",
                        "shear_00", "shear_00_af", "shear_00_ziegler", "bauschinger_00", "bauschinger_00_af", "bauschinger_00_ziegler"})
    scenes.push_back(std::string("experiments/aa3003o/scenes/") + n + ".toml");
  spifit::test::check_golden_outputs(scenes);
}

TEST(GoldenOutputs, ShellBenchmarks) {
  std::vector<std::string> scenes;
  for (const char* n : {"bending_patch", "membrane_patch", "cantilever_shear", "cantilever_rollup", "limit_moment", "limit_moment_surface",
                        "pinched_hemisphere", "pinched_hemisphere_8x8", "scordelis_lo", "scordelis_lo_8x8", "twisted_beam_in_plane",
                        "twisted_beam_out_of_plane"})
    scenes.push_back(std::string("experiments/benchmarks/") + n + ".toml");
  spifit::test::check_golden_outputs(scenes);
}

TEST(GoldenOutputs, FormingScenes) {
  spifit::test::check_golden_outputs({"experiments/aa3003o/scenes/indent.toml", "experiments/aa3003o/scenes/indent_explicit.toml",
                                      "experiments/aa3003o/scenes/indent_brick.toml",
                                      "experiments/aa3003o/scenes/indent_line.toml",
                                      "experiments/aa3003o/scenes/indent_line_c7_af.toml",
                                      "experiments/aa3003o/scenes/indent_line_c8_ziegler.toml"});
}

TEST(GoldenOutputs, ConeScenes) {
  spifit::test::check_golden_outputs({"experiments/aa3003o/scenes/cone70_pie45_short.toml", "experiments/aa3003o/scenes/cone50_pie45_10.toml"});
}
