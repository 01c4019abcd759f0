// G-code tool paths: forward/toolpath/gcode.hpp.
#include "forward/toolpath/gcode.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return spifit::fuzz::read_bytes_as_file(data, size, ".nc", [](const std::string& p) { (void)spifit::toolpath::read_gcode(p); });
}
