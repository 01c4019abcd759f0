// A worker's forward runs in child processes: a child that ends before reading its job must not
// end the worker with it (an MPI fit's rank died of SIGPIPE when a run's process was killed just
// after it started).
#include "cli/job_process.hpp"

#include <gtest/gtest.h>

#include <string>

namespace spifit::cli {
namespace {

TEST(JobProcess, AChildThatEndsWithoutReadingItsJobDoesNotEndTheParent) {
  // The child is this test program (/proc/self/exe) running no test: it ends at once without
  // reading its stdin, while the parent is still writing a job far larger than a pipe's buffer.
  const std::string job(std::size_t{4} << 20, 'x');
  const ChildOutcome c = run_child({"--gtest_filter=-*"}, job, 0.0);
  EXPECT_TRUE(c.ok) << c.why;
  EXPECT_NE(c.output.find("0 tests"), std::string::npos) << c.output;
}

}  // namespace
}  // namespace spifit::cli
