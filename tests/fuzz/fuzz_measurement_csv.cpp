// Measurement CSV files: inverse/experiments/measurement.hpp.
#include "inverse/experiments/measurement.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return spifit::fuzz::read_bytes_as_file(data, size, ".csv", [](const std::string& p) {
    auto t = spifit::inverse::read_measurement_csv(p);
    for (const std::string& name : t.names) spifit::inverse::convert_column(t, name, "MPa");
  });
}
