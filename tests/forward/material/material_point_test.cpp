// Commit / revert semantics of one integration point: s1 is only committed when the global
// step converged.
#include "forward/material/material_point.hpp"
#include "tests/support/cards.hpp"

#include <gtest/gtest.h>

using namespace spifit::material;

TEST(MaterialPoint, CommitAndRevert) {
  const auto card = spifit::test::card("aa3003o_c7_af_shell");
  const ReturnMapping<double, 3> law(card.params);
  MaterialPoint<double, 3> mp(law);
  const Eigen::Vector3d de(0.01, -0.004, 0.002);
  ASSERT_TRUE(mp.update(de, nullptr).ok());
  EXPECT_GT(mp.trial().eqps, 0.0);
  EXPECT_EQ(mp.committed().eqps, 0.0);  // not committed yet
  mp.revert();
  EXPECT_EQ(mp.trial().eqps, 0.0);
  ASSERT_TRUE(mp.update(de, nullptr).ok());
  const double p1 = mp.trial().eqps;
  mp.commit();
  EXPECT_EQ(mp.committed().eqps, p1);
  // A second update starts from the committed state, and a failed one leaves it untouched.
  ASSERT_TRUE(mp.update(de, nullptr).ok());
  EXPECT_GT(mp.trial().eqps, p1);
  const auto bad = mp.update(Eigen::Vector3d(std::nan(""), 0.0, 0.0), nullptr);
  EXPECT_FALSE(bad.ok());
  EXPECT_EQ(mp.committed().eqps, p1);
  EXPECT_TRUE(mp.committed().stress.allFinite());
}

// The yield stress a state keeps (so that the next elastic check needs no pow) is bit for bit
// the one computed from its eqps, and a state without it (fresh, or read from a checkpoint)
// integrates to the same bits as one with it.
TEST(MaterialPoint, KeptFlowStressIsBitForBitTheComputedOne) {
  for (const char* name : {"aa3003o_c3c4", "aa3003o_c7_af_shell", "aa3003o_c8_ziegler_shell"}) {
    SCOPED_TRACE(name);
    const auto card = spifit::test::card(name);
    const ReturnMapping<double, 3> law(card.params);
    MaterialPoint<double, 3> kept(law), fresh(law);
    const Eigen::Vector3d steps[] = {{0.01, -0.004, 0.002}, {0.002, 0.0, 0.0}, {-1e-5, 0.0, 0.0}, {-0.02, 0.01, 0.0}};
    for (const auto& de : steps) {
      ASSERT_TRUE(kept.update(de, nullptr).ok());
      kept.commit();
      EXPECT_EQ(kept.committed().flow_stress, law.yield_stress(kept.committed().eqps));
      auto forgotten = kept.committed();  // as load_state leaves it
      forgotten.flow_stress = -1.0;
      fresh.set_committed(forgotten);
      ASSERT_TRUE(fresh.update(de, nullptr).ok());
      ASSERT_TRUE(kept.update(de, nullptr).ok());
      for (int i = 0; i < 3; ++i) EXPECT_EQ(fresh.trial().stress(i), kept.trial().stress(i));
      EXPECT_EQ(fresh.trial().eqps, kept.trial().eqps);
      kept.revert();
    }
  }
}
