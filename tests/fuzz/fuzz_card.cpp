// Material cards: forward/material/material_card.hpp.
#include "forward/material/material_card.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return spifit::fuzz::read_bytes_as_file(data, size, ".toml", [](const std::string& p) { (void)spifit::material::load_material_card(p); });
}
