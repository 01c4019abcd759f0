// A fit's progress (inverse/fit/fit_progress.hpp): the runs counted per iteration, the time left of
// an iteration from the median run time and the runs that go side by side, and the events in the
// order they happened however many threads end runs at once.
#include "inverse/fit/fit_progress.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

namespace spifit::inverse {
namespace {

TEST(FitProgress, TheTimeLeftOfAnIterationIsTheMedianRunTimesItsBatchesToCome) {
  std::vector<FitProgressEvent> seen;
  FitProgress p([&](const FitProgressEvent& e) { seen.push_back(e); });
  p.configure(11, 2);  // 1 + 2p runs of one scene file, p = 5; two at a time
  p.run_finished(4.0);
  p.run_finished(6.0);
  p.run_finished(5.0);
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_EQ(seen.back().runs, 3);
  EXPECT_EQ(seen.back().runs_expected, 11);
  EXPECT_DOUBLE_EQ(seen.back().median_run_seconds, 5.0);
  EXPECT_DOUBLE_EQ(seen.back().seconds_left, 4 * 5.0);  // 8 runs left: 4 batches of 2
  p.iteration_finished(0, 12.5);
  EXPECT_EQ(seen.back().kind, FitProgressEvent::Kind::iteration);
  EXPECT_EQ(seen.back().iteration, 0);
  EXPECT_EQ(seen.back().runs, 3);
  EXPECT_DOUBLE_EQ(seen.back().cost, 12.5);
  p.run_finished(7.0);  // the next iteration's first run
  EXPECT_EQ(seen.back().iteration, 1);
  EXPECT_EQ(seen.back().runs, 1);
  EXPECT_EQ(seen.back().runs_total, 4);
  EXPECT_DOUBLE_EQ(seen.back().median_run_seconds, 6.0);  // of 4, 5, 6, 7: the upper middle
  p.set_phase("start 2 of 3");
  EXPECT_EQ(p.snapshot().phase, "start 2 of 3");
  EXPECT_EQ(p.snapshot().iteration, 0);
  EXPECT_EQ(p.snapshot().runs, 0);
}

TEST(FitProgress, EventsArriveInTheOrderTheyHappened) {
  std::vector<long> runs;  // written by the sink only: called one at a time
  FitProgress p([&](const FitProgressEvent& e) {
    if (e.kind == FitProgressEvent::Kind::run) runs.push_back(e.runs);
  });
  p.configure(400, 4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&p] {
      for (int i = 0; i < 100; ++i) p.run_finished(0.001);
    });
  for (auto& t : threads) t.join();
  ASSERT_EQ(runs.size(), 400u);
  for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i], static_cast<long>(i + 1)) << i;
}

}  // namespace
}  // namespace spifit::inverse
