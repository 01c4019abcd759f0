// Fit files: inverse/fit/fit_file.hpp.
#include "inverse/fit/fit_file.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return spifit::fuzz::read_bytes_as_file(data, size, ".toml", [](const std::string& p) { (void)spifit::inverse::read_fit_file(p); }, "");
}
