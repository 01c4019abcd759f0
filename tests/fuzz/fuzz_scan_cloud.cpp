// Laser-scan point clouds: inverse/experiments/scan_section.hpp.
#include "inverse/experiments/scan_section.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return spifit::fuzz::read_bytes_as_file(data, size, ".csv", [](const std::string& p) { (void)spifit::inverse::read_scan_cloud(p); });
}
