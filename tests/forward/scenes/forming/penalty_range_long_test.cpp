// Long (ctest -L long): the §7.1 indent over the whole penalty range 1e1..1e7 N/mm^3 (the
// thesis's code failed above 1e5). Every value converges; the force settles; from 1e5 upward
// the penetration falls in proportion to 1/K_p (docs/results/validation.md, "Indent", has the table).
#include "forward/scenes/forming/forming_run.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace spifit::scene {
namespace {

TEST(IndentPenaltyRange, ConvergesFromTenToTenMillion) {
  const FormingScene base = read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/indent.toml");
  std::vector<double> pen, force;
  for (double kp : {1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7}) {
    FormingScene s = base;
    s.contact.penalty = kp;
    const FormingResult r = run_forming_scene(s);  // in memory
    ASSERT_TRUE(r.ok()) << "K_p " << kp << ": " << r.message;
    pen.push_back(r.force.max_penetration());
    force.push_back(r.force.final_force().z());
    std::printf("K_p %.0e: Fz %.4f N, max penetration %.4e mm, %d increments, %d iterations, %.2f s\n", kp, force.back(),
                pen.back(), r.run.counters.increments, r.run.counters.iterations, r.wall_seconds);
  }
  for (std::size_t i = 4; i + 1 < pen.size(); ++i) EXPECT_NEAR(pen[i] / pen[i + 1], 10.0, 0.6);  // 1/K_p from 1e5 on
  for (std::size_t i = 4; i < force.size(); ++i) EXPECT_NEAR(force[i] / force.back(), 1.0, 1e-3);
}

}  // namespace
}  // namespace spifit::scene
