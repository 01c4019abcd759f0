// Messages a user test found misleading: each names what is wrong (file, key, value) and exits
// with 2, the code of a usage or input error (docs/cli.md).
#include "tests/cli/cli_support.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

using spifit::test::run_spifit;

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

// No byte a terminal must not get raw: control characters and bytes of no UTF-8 character.
bool printable(const std::string& s) {
  for (unsigned char c : s)
    if ((c < 0x20 && c != '\n') || c == 0x7f || c >= 0x80) return false;
  return true;
}

// A binary file given as a cloud: its bytes quoted, the message short.
TEST(MessagesCli, ABinaryCloudIsQuotedAndCut) {
  std::string bytes = "\x89PNG\r\n\x1a\n";
  for (int i = 0; i < 3000; ++i) bytes += static_cast<char>((i * 37 + 11) % 256);
  const fs::path cloud = spifit::test::write_temp_file("cloud.png", bytes);
  const fs::path out = spifit::test::temp_path("png_out");
  fs::remove_all(out);
  const auto r = run_spifit("scan " + cloud.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_TRUE(printable(r.err)) << r.err;
  EXPECT_LT(r.err.size(), 400u) << r.err;
  EXPECT_NE(r.err.find(cloud.string() + ": line 1 = \\x89PNG: not text (byte \\x89 at position 1)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(cloud);
}

}  // namespace
