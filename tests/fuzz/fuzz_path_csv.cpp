// Tool-path CSV files: forward/toolpath/path_csv.hpp.
#include "forward/toolpath/path_csv.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return spifit::fuzz::read_bytes_as_file(data, size, ".csv", [](const std::string& p) { (void)spifit::toolpath::read_path_csv(p, 10.0); });
}
