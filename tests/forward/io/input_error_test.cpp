// io::one_line and InputError's text: one line, bytes a terminal must not get raw quoted as
// \xNN, valid UTF-8 kept, long values cut so that the message still follows.
#include "forward/io/input_error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace spifit::io {
namespace {

TEST(InputErrorText, QuotesControlBytesAndInvalidUtf8) {
  EXPECT_EQ(one_line(std::string("a\0b\x1b[2Jc", 8)), "a\\x00b\\x1B[2Jc");
  EXPECT_EQ(one_line("x\x7fy"), "x\\x7Fy");
  EXPECT_EQ(one_line("\x89PNG"), "\\x89PNG");
  EXPECT_EQ(one_line("\xE2\x82"), "\\xE2\\x82");  // a character cut short
  EXPECT_EQ(one_line("\xC2\x9B" "1m"), "\\xC2\\x9B1m");  // U+009B, a terminal's CSI
  EXPECT_EQ(one_line("\xED\xA0\x80"), "\\xED\\xA0\\x80");  // a UTF-16 surrogate, no character
  EXPECT_EQ(one_line("\xE0\x80\xAF"), "\\xE0\\x80\\xAF");  // an overlong '/'
  EXPECT_EQ(one_line("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(one_line("§7.1, 45°, \xE2\x82\xAC"), "§7.1, 45°, €");
  EXPECT_EQ(one_line("two\nlines\t and  blanks "), "two lines and blanks");
}

TEST(InputErrorText, CutsAtWholeCharactersAndEscapes) {
  const std::string cut = one_line(std::string(8, '\x01'), 20);  // 8 escapes of 4 bytes
  EXPECT_EQ(cut, "\\x01\\x01\\x01\\x01...");
  EXPECT_EQ(one_line(std::string(10, 'a') + "§§§§", 15), "aaaaaaaaaa§...");
}

TEST(InputErrorText, LongValuesAreCutBeforeTheMessage) {
  const InputError e("f.csv", "line 1", std::string(5000, 'z'), "not a finite number");
  const std::string what = e.what();
  EXPECT_LT(what.size(), 150u);
  EXPECT_EQ(what.rfind("f.csv: line 1 = zzz", 0), 0u) << what;
  EXPECT_NE(what.find("...: not a finite number"), std::string::npos) << what;
  EXPECT_EQ(e.value().size(), 5000u);  // the value itself is kept whole
}

}  // namespace
}  // namespace spifit::io
