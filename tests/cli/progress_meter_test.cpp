// The progress lines of long runs and fits (cli/progress_meter.hpp, cli/fit_progress_lines.hpp)
// on made-up times: silent for the first seconds, a line every interval in a log, the line
// rewritten on a terminal, the estimate of the time left from the recent rate, and a fit's lines
// per iteration and per FE run.
#include "cli/fit_progress_lines.hpp"
#include "cli/progress_meter.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace spifit::cli {
namespace {

TEST(ProgressMeter, TheLineSaysHowFarHowLongAndHowMuchLonger) {
  EXPECT_EQ(ProgressMeter::line(0.25, 62.0, 186.0), "25.0 % of the tool path, 1:02 elapsed, about 3:06 left");
  EXPECT_EQ(ProgressMeter::line(0.005, 62.0, std::nullopt), "0.5 % of the tool path, 1:02 elapsed");  // no estimate yet
  EXPECT_EQ(ProgressMeter::line(0.5, 4000.0, 4000.0), "50.0 % of the tool path, 1:06:40 elapsed, about 1:06:40 left");
  EXPECT_EQ(ProgressMeter::line(1.0, 10.0, 0.0), "100.0 % of the tool path, 0:10 elapsed");
}

TEST(RemainingTime, TheSetUpAndASlowStartDoNotWeighOnceTheRunHasSettled) {
  // 5 s of set-up before the first increment, a slow first 10 % over 10 s, then 2 % per second:
  // the end comes at 15 + 45 = 60 s.
  RemainingTime left;
  EXPECT_FALSE(left.seconds());
  for (int i = 0; i <= 10; ++i) left.add(0.01 * i, 5.0 + i);
  for (int i = 1; i <= 20; ++i) left.add(0.1 + 0.02 * i, 15.0 + i);  // 50 % at 35 s
  ASSERT_TRUE(left.seconds());
  EXPECT_NEAR(*left.seconds(), 25.0, 1e-9);  // the recent rate: 50 % left at 2 % per second
  // Since the start, as before: 35 s for 50 % would say 35 s.
}

TEST(RemainingTime, NoEstimateBeforeOnePercentOrTwoSeconds) {
  RemainingTime left;
  left.add(0.0, 10.0);
  left.add(0.005, 13.0);
  EXPECT_FALSE(left.seconds());  // 0.5 %
  RemainingTime quick;
  quick.add(0.0, 10.0);
  quick.add(0.2, 11.0);
  EXPECT_FALSE(quick.seconds());  // 1 s after the first increment
  quick.add(0.4, 12.0);
  ASSERT_TRUE(quick.seconds());
  EXPECT_NEAR(*quick.seconds(), 3.0, 1e-12);  // 60 % at 20 % per second
}

TEST(ProgressMeter, ALogGetsALineEveryIntervalAfterTheFirstSeconds) {
  ProgressMeter m(false, 30.0, 3.0);
  EXPECT_FALSE(m.update(0.0, 0.5));
  EXPECT_FALSE(m.update(0.1, 1.0));  // a short run prints nothing
  const auto first = m.update(0.2, 3.5);
  ASSERT_TRUE(first);
  EXPECT_EQ(*first, "spifit: 20.0 % of the tool path, 0:04 elapsed, about 0:12 left\n");  // 20 % in 3 s since the first increment
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

inverse::FitProgressEvent event(inverse::FitProgressEvent::Kind kind, int iteration, long runs, double elapsed) {
  inverse::FitProgressEvent e;
  e.kind = kind;
  e.iteration = iteration;
  e.runs = runs;
  e.runs_expected = 11;
  e.runs_total = 11 + runs;
  e.cost = 12.5;
  e.elapsed = elapsed;
  e.median_run_seconds = 4.0;
  e.seconds_left = 4.0 * std::ceil((11.0 - static_cast<double>(runs)) / 2.0);
  return e;
}

TEST(FitProgressLines, AnIterationLineStaysAndRunLinesSayWhatIsLeftOfTheIteration) {
  using Kind = inverse::FitProgressEvent::Kind;
  EXPECT_EQ(FitProgressLines::iteration_line(event(Kind::iteration, 1, 11, 62.0)), "iteration 1: cost 12.5, 11 FE runs (22 in all), 1:02 elapsed");
  EXPECT_EQ(FitProgressLines::run_line(event(Kind::run, 2, 5, 80.0)), "iteration 2: FE run 5 of 11, 1:20 elapsed, about 0:12 left in this iteration");
  FitProgressLines log(false, 30.0);
  EXPECT_EQ(*log.update(event(Kind::run, 2, 1, 10.0)), "spifit: iteration 2: FE run 1 of 11, 0:10 elapsed, about 0:20 left in this iteration\n");
  EXPECT_FALSE(log.update(event(Kind::run, 2, 2, 20.0)));  // within the log interval
  EXPECT_EQ(*log.update(event(Kind::iteration, 2, 11, 25.0)), "spifit: iteration 2: cost 12.5, 11 FE runs (22 in all), 0:25 elapsed\n");
  EXPECT_TRUE(log.update(event(Kind::run, 3, 1, 26.0)));  // a new iteration's first run
  FitProgressLines terminal(true);
  EXPECT_EQ(terminal.update(event(Kind::run, 0, 1, 1.0))->front(), '\r');
  EXPECT_EQ(*terminal.finish(), "\n");
  EXPECT_EQ(terminal.update(event(Kind::iteration, 0, 11, 5.0))->back(), '\n');
  EXPECT_FALSE(terminal.finish());
}

TEST(FitProgressLines, AFitOfMaterialPointsIsSilentForItsFirstSeconds) {
  inverse::FitProgressEvent e;
  e.kind = inverse::FitProgressEvent::Kind::iteration;
  e.cost = 3.0;
  e.elapsed = 0.05;
  FitProgressLines lines(false);
  EXPECT_FALSE(lines.update(e));
  e.elapsed = 2.5;
  EXPECT_EQ(*lines.update(e), "spifit: iteration 0: cost 3, 0:03 elapsed\n");
}

TEST(FitProgressLines, TheRunningSummarySaysWhereTheFitIs) {
  const auto j = fit_progress_json(event(inverse::FitProgressEvent::Kind::run, 2, 5, 80.0));
  EXPECT_EQ(j["iteration"], 2);
  EXPECT_EQ(j["iteration_runs"], 5);
  EXPECT_EQ(j["iteration_runs_expected"], 11);
  EXPECT_EQ(j["forward_runs"], 16);
  EXPECT_DOUBLE_EQ(j["iteration_seconds_left"].get<double>(), 12.0);
}

}  // namespace
}  // namespace spifit::cli
