// Long (ctest -L long): the §7.1 indent over the whole penalty range 1e1..1e7 N/mm^3 (the
// thesis's code failed above 1e5). Every value converges; the force settles; from 1e5 upward
// the penetration falls in proportion to 1/K_p (docs/contact.md has the table).
#include "forward/scenes/forming/forming_scene.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace spifit::scene {
namespace {

TEST(IndentPenaltyRange, ConvergesFromTenToTenMillion) {
  const FormingScene base = read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/indent.toml");
  const auto dir = std::filesystem::temp_directory_path() / ("spifit_penalty_" + std::to_string(::getpid()));
  std::vector<double> pen, force;
  for (double kp : {1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7}) {
    FormingScene s = base;
    s.contact.penalty = kp;
    const auto out = io::OutputDirectory::prepare(dir.string(), true);
    const FormingReport r = run_forming_scene(s, out);
    ASSERT_TRUE(r.ok) << "K_p " << kp << ": " << r.summary.dump();
    pen.push_back(r.summary["max_penetration"].get<double>());
    force.push_back(r.summary["final_force"][2].get<double>());
    std::printf("K_p %.0e: Fz %.4f N, max penetration %.4e mm, %d increments, %d iterations, %.2f s\n", kp, force.back(),
                pen.back(), r.summary["increments"].get<int>(), r.summary["newton_iterations"].get<int>(),
                r.summary["wall_seconds"].get<double>());
  }
  std::filesystem::remove_all(dir);
  for (std::size_t i = 4; i + 1 < pen.size(); ++i) EXPECT_NEAR(pen[i] / pen[i + 1], 10.0, 0.6);  // 1/K_p from 1e5 on
  for (std::size_t i = 4; i < force.size(); ++i) EXPECT_NEAR(force[i] / force.back(), 1.0, 1e-3);
}

}  // namespace
}  // namespace spifit::scene
