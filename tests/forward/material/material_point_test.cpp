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
