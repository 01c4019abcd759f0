// The progress line of long runs (cli/progress_meter.hpp) on made-up times: silent for the
// first seconds, a line every interval in a log, the line rewritten on a terminal, and the
// estimate of the time left.
#include "cli/progress_meter.hpp"

#include <gtest/gtest.h>

namespace spifit::cli {
namespace {

TEST(ProgressMeter, TheLineSaysHowFarHowLongAndHowMuchLonger) {
  EXPECT_EQ(ProgressMeter::line(0.25, 62.0), "25.0 % of the tool path, 1:02 elapsed, about 3:06 left");
  EXPECT_EQ(ProgressMeter::line(0.005, 62.0), "0.5 % of the tool path, 1:02 elapsed");  // too early to estimate
  EXPECT_EQ(ProgressMeter::line(0.5, 4000.0), "50.0 % of the tool path, 1:06:40 elapsed, about 1:06:40 left");
  EXPECT_EQ(ProgressMeter::line(1.0, 10.0), "100.0 % of the tool path, 0:10 elapsed");
}

TEST(ProgressMeter, ALogGetsALineEveryIntervalAfterTheFirstSeconds) {
  ProgressMeter m(false, 30.0, 3.0);
  EXPECT_FALSE(m.update(0.1, 1.0));  // a short run prints nothing
  const auto first = m.update(0.2, 3.5);
  ASSERT_TRUE(first);
  EXPECT_EQ(*first, "spifit: 20.0 % of the tool path, 0:04 elapsed, about 0:14 left\n");
  EXPECT_FALSE(m.update(0.3, 20.0));
  EXPECT_TRUE(m.update(0.9, 33.6));
  EXPECT_FALSE(m.finish());
}

TEST(ProgressMeter, ATerminalLineIsRewrittenInPlace) {
  ProgressMeter m(true);
  const auto a = m.update(0.5, 4.0);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->front(), '\r');
  EXPECT_FALSE(m.update(0.51, 4.2));
  EXPECT_TRUE(m.update(0.52, 4.6));
  EXPECT_EQ(*m.finish(), "\n");
}

}  // namespace
}  // namespace spifit::cli
