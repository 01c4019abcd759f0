// TomlTable::parse_file on files that are no UTF-8 text: a clear error naming the file, the line
// and the byte, given before toml11 parses anything. The file of the fuzzer's finding (a literal
// string holding invalid UTF-8, on which toml11 3.7.1 reads past its buffer) is one of them.
#include "forward/io/input_error.hpp"
#include "forward/io/toml_reader.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace spifit::io {
namespace {

std::string parse_error(const std::string& path) {
  try {
    (void)TomlTable::parse_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string write_file(const std::string& name, const std::string& bytes) {
  const std::string path = test::temp_path(name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(TomlReader, InvalidUtf8IsReportedWithItsLineAndByte) {
  const std::string path = write_file("toml_reader_latin1.toml", "[card]\nname = 'Gr\xFC\x65nwald'\n");
  const std::string e = parse_error(path);
  EXPECT_EQ(e.rfind(path + ": not a text file: line 2 holds byte \\xFC", 0), 0u) << e;
}

TEST(TomlReader, TheFuzzersFileIsRejectedAsNoText) {
  const std::string path = std::string(SPIFIT_SOURCE_DIR) + "/tests/fuzz/corpus/card/toml11_invalid_utf8_literal_key.toml";
  const std::string e = parse_error(path);
  EXPECT_NE(e.find("not a text file: line 1 holds byte \\xCA"), std::string::npos) << e;
}

TEST(TomlReader, SurrogatesAndOverlongFormsAreNoText) {
  EXPECT_NE(parse_error(write_file("toml_reader_surrogate.toml", "a = '\xED\xA0\x80'\n")).find("byte \\xED"), std::string::npos);
  EXPECT_NE(parse_error(write_file("toml_reader_overlong.toml", "a = '\xE0\x80\xAF'\n")).find("byte \\xE0"), std::string::npos);
  EXPECT_NE(parse_error(write_file("toml_reader_nul.toml", std::string("a = 1\0", 6))).find("byte \\x00"), std::string::npos);
}

TEST(TomlReader, CrLfTabsAndUtf8AreText) {
  const auto t = TomlTable::parse_file(write_file("toml_reader_crlf.toml", "name\t= '45° §7.1 €'\r\nt = 1.5\r\n"));
  EXPECT_EQ(t.string("name"), "45° §7.1 €");
  EXPECT_DOUBLE_EQ(t.number("t"), 1.5);
}

}  // namespace
}  // namespace spifit::io
