// A numerical failure in words (forward/scenes/common/failure_words.hpp): the solver's messages
// of an element turned inside out, a run-away step, a singular tangent and a Newton that does not
// settle get the likely cause and what to change, with the solver's own words kept.
#include "forward/scenes/common/failure_words.hpp"

#include <gtest/gtest.h>

namespace spifit::scene {
namespace {

TEST(FailureWords, TheLikelyCauseFirstTheSolversWordsKept) {
  const std::string inverted =
      "increment from load factor 0.42 failed at the minimum increment 1e-05: layer stretched to a non-positive metric (det C = -42.9) (element 17)";
  const std::string said = failure_in_words(inverted);
  EXPECT_EQ(said.rfind("an element was turned inside out where the tool pushes", 0), 0u) << said;
  EXPECT_NE(said.find("take smaller increments (solver.travel_per_increment), a finer mesh under the tool"), std::string::npos) << said;
  EXPECT_NE(said.find("(solver: " + inverted + ")"), std::string::npos) << said;
  EXPECT_EQ(failure_in_words("increment from load factor 0.1 failed at the minimum increment 1e-05: Newton iterations diverging (relative residual 3)")
                .rfind("the sheet's equilibrium could not be found", 0),
            0u);
  EXPECT_EQ(failure_in_words("... : linear solver: UMFPACK: matrix is singular").rfind("the sheet lost its stiffness", 0), 0u);
  EXPECT_EQ(failure_in_words("... : no convergence in 25 iterations (relative residual 0.01)").rfind("the sheet's equilibrium was not reached", 0), 0u);
  EXPECT_EQ(failure_in_words("something no rule knows"), "something no rule knows");
}

}  // namespace
}  // namespace spifit::scene
