#pragma once
// Errors a user can cause (bad file, key or value). Reported on one line as
//   FILE: KEY = VALUE: what is wrong
// by the CLI, with exit code 2. Numerical failures are not InputErrors.
#include <stdexcept>
#include <string>

namespace spifit::io {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string key, std::string value, std::string message);
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const std::string& value() const { return value_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_, key_, value_, message_;
};

// Collapses a (possibly multi-line) text to one line of at most max_chars bytes ("..." at the
// end when cut). Bytes a terminal must not get raw (control characters other than blanks, bytes
// that are not valid UTF-8, e.g. of a binary file) are written as \xNN; valid UTF-8 is kept.
std::string one_line(const std::string& text, std::size_t max_chars = 200);
// The length in bytes of the valid UTF-8 character at text[i] (1 for printable ASCII); 0 for a
// control character or a byte that starts no valid UTF-8 character.
std::size_t printable_length(const std::string& text, std::size_t i);
// The first byte of text that is no text: a control character other than tab, CR and LF, or a
// byte of no valid UTF-8 character (RFC 3629; a binary file); npos when there is none.
std::size_t first_non_text(const std::string& text);
// The text without leading and trailing blanks (spaces, tabs, CR, LF).
std::string trim(const std::string& text);
// Shortest round-trip text for a number, as written in an error message.
std::string format_number(double v);

}  // namespace spifit::io
