#pragma once
// The message of the io::InputError an input reader throws, for tests of error messages.
#include "forward/io/input_error.hpp"

#include <string>

namespace spifit::test {

// What read() throws as an io::InputError; `none` when it throws nothing.
template <typename Read>
std::string input_error_of(Read read, const std::string& none = "(no error)") {
  try {
    read();
  } catch (const io::InputError& e) {
    return e.what();
  }
  return none;
}

}  // namespace spifit::test
