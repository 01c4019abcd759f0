// spifit inputs: the kinds, a kind's keys and observables, and the Markdown reference that
// docs/reference/input-reference.md must equal (regenerate: spifit inputs --markdown > docs/reference/input-reference.md).
#include "tests/cli/cli_support.hpp"
#include "forward/io/text_file.hpp"

#include <gtest/gtest.h>

TEST(InputsCli, TheDocumentedReferenceIsTheGeneratedOne) {
  const auto r = spifit::test::run_spifit("inputs --markdown");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, spifit::io::read_text_file(std::string(SPIFIT_SOURCE_DIR) + "/docs/reference/input-reference.md"))
      << "docs/reference/input-reference.md is stale: spifit inputs --markdown > docs/reference/input-reference.md";
}

TEST(InputsCli, KindsAndOneKindsKeys) {
  auto r = spifit::test::run_spifit("inputs");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* k : {"tensile", "shell_benchmark", "indent_line", "cone"}) EXPECT_NE(r.out.find(k), std::string::npos) << k;
  r = spifit::test::run_spifit("inputs cone");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("| `contact.friction` | number | - | [0, 2] | yes |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("`steady_fz`"), std::string::npos) << r.out;
  r = spifit::test::run_spifit("inputs conee");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("KIND = conee: unknown scene kind (known: "), std::string::npos) << r.err;
}
